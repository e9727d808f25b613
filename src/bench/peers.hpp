// Peers: the engines and libraries users would otherwise pick (Boost.odeint,
// Bullet, ODE), run on torque-free bodies next to tumble's own methods. Each
// lives in its own file; Bullet and ODE sit behind #if (odeint ships with Boost).
#pragma once

#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "bench/studies.hpp"

namespace tumble::bench {

/// One body advanced step by step (the stability map and flip studies watch
/// every step). Bodies are torque-free, in their principal frame.
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
/// tumble's rk45 in the bench). `make` steps at a fixed h (an adaptive
/// configuration's underlying pair, as rk45 on the stability map).
struct PeerConfig {
  std::string label;       ///< "odeint_rk4_body", "bullet_none", ...
  std::string param_name;  ///< "dt" or "rtol"
  std::function<BodyState(const RigidBodyModel&, const BodyState&, double T, double param)> run;
  MakeStepper make;
};

/// A fixed-step configuration whose run is `make` stepped n = round(T/dt) times.
PeerConfig stepped_peer(std::string label, MakeStepper make);

/// Every compiled-in peer configuration, odeint first.
std::vector<PeerConfig> peer_configs();

/// Something that steps at a fixed h: every tumble method, then every peer.
struct Contender {
  std::string name;
  MakeStepper make;
};
std::vector<Contender> stepped_contenders();

/// n = round(T/dt) steps of h = T/n with a fresh stepper; the final state.
BodyState run_stepper(const MakeStepper& make, const RigidBodyModel& m, const BodyState& s0, double T, double dt);

/// "Boost.odeint 1.81 (header-only)", "Bullet 3.24 (double)", ...
std::vector<std::string> peers_found();
/// One markdown bullet per engine: what was set and why.
std::string peer_settings_markdown();
/// Work-precision rows of every peer configuration on a torque-free problem
/// (problem name = p.name, method = peer label), over a dt or rtol sweep.
std::vector<WpRow> peer_work_precision(const Problem& p, const Settings& st, std::ostream& log);

// Per-engine configuration lists (Bullet and ODE defined only when found).
std::vector<PeerConfig> odeint_configs();
std::vector<PeerConfig> bullet_configs();
std::vector<PeerConfig> ode_configs();

}  // namespace tumble::bench
