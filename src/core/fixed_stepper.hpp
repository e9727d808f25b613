// One body stepped by a fixed-step method the way a run steps it: in Euler's
// coordinates carried from step to step when the method integrates in them
// (MethodInfo::coords_step: rk4), otherwise on the seed's state through
// step(), or with the sub-flow order fixed from the start when the method's
// best order depends on it (MethodInfo::ordered_step: splitting). The Propagator adds the grid, sampling and the divergence guard;
// tumble bench steps its methods through this too, so the charts show what a
// run does.
#pragma once

#include <optional>

#include "core/body.hpp"
#include "core/body_frame.hpp"
#include "core/integrator.hpp"

namespace tumble {

class FixedStepper {
 public:
  FixedStepper(Method method, const RigidBodyModel& m, const BodyState& s0);

  /// One step from time t (s) by h (s). Keeps q in the hemisphere of the last
  /// one (q and -q are the same rotation; outputs stay continuous in time).
  void step(double t, double h);
  /// The seed's state (c, q, P, L) now; q unit.
  BodyState state() const;
  /// The carried coordinates, or nullptr for methods on the seed's state.
  const BodyCoords* coords() const { return coords_ ? &*coords_ : nullptr; }
  /// The state itself, for methods on the seed's state (coords() == nullptr).
  const BodyState& seed_state() const { return s_; }
  /// A partial step of h from here, not kept (dense output between grid points).
  BodyState peek(double t, double h) const;

 private:
  BodyState seed_step(const BodyState& s, double t, double h) const;

  const RigidBodyModel* m_;
  const MethodInfo* info_;
  BodyState s_;                       // the state, when not carried in coords_
  std::optional<BodyCoords> coords_;
  int order_ = -1;                    // sub-flow order fixed at the start, or -1
};

/// n fixed steps of h (s) from s0 at t0 (s), as a run takes them, no guard.
BodyState integrate_fixed(Method method, const RigidBodyModel& m, const BodyState& s0, double t0, double h, long n);

}  // namespace tumble
