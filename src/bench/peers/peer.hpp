// What a peer is: the engines and libraries users would otherwise pick
// (Boost.odeint, Bullet, ODE), each in its own file that describes itself as a
// PeerEngine. This header is all a peer's file includes; the registry of
// engines (peers.hpp) includes the peers, never the other way round.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/body.hpp"
#include "core/integrator.hpp"

namespace tumble::bench {

/// One body advanced step by step (the stability map and flip studies watch
/// every step). Bodies are in their principal frame.
class Stepper {
 public:
  virtual ~Stepper() = default;
  virtual void step(double h) = 0;       ///< one step of h (s)
  virtual BodyState state() const = 0;   ///< the seed's (c, q, P, L), world frame
};
using MakeStepper = std::function<std::unique_ptr<Stepper>(const RigidBodyModel&, const BodyState&)>;

/// A tumble method as a Stepper (tracks t for the force terms).
std::unique_ptr<Stepper> method_stepper(Method method, const RigidBodyModel& m, const BodyState& s0);

/// One peer configuration. `run` integrates s0 to T (s) at one `param_name`
/// value: dt (s) for fixed steps, rtol for adaptive ones (atol = rtol, as
/// tumble's adaptive pairs in the bench). `make` steps at a fixed h (an
/// adaptive configuration's underlying pair, as rk45 on the stability map).
struct PeerConfig {
  std::string label;       ///< "odeint_rk4_body", "bullet_none", ...
  std::string param_name;  ///< "dt" or "rtol"
  std::function<BodyState(const RigidBodyModel&, const BodyState&, double T, double param)> run;
  MakeStepper make;
  bool forces = false;     ///< also runs forced bodies (tumble's forces, same right-hand side)
};

/// A fixed-step configuration whose run is `make` stepped n = round(T/dt) times.
PeerConfig stepped_peer(std::string label, MakeStepper make);

/// n = round(T/dt) steps of h = T/n with a fresh stepper; the final state.
BodyState run_stepper(const MakeStepper& make, const RigidBodyModel& m, const BodyState& s0, double T, double dt);

/// One engine as its own file describes it.
struct PeerEngine {
  std::string found;     ///< "Boost.odeint 1.83 (header-only, libboost-dev)"; empty when not compiled in
  std::string settings;  ///< one markdown bullet: what was set and why (or how to get the engine)
  std::vector<PeerConfig> configs;
};

// The engines, each defined in its own file (*_peer.cpp), found or not.
PeerEngine odeint_engine();
PeerEngine bullet_engine();
PeerEngine ode_engine();

}  // namespace tumble::bench
