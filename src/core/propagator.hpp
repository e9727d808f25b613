// Advances one body through a run, sample time by sample time, with the
// numeric-failure guard (issue #5 §3).
#pragma once

#include <memory>
#include <optional>

#include "core/body.hpp"
#include "core/free_rotation_exact.hpp"
#include "core/integrator.hpp"
#include "core/rk45.hpp"

namespace tumble {

struct StepConfig {
  Method method = Method::rk4;
  double dt = 1e-3;         ///< s, fixed step (rk45: its largest step)
  double rtol = 1e-9;       ///< rk45 only
  double atol = 1e-12;      ///< rk45 only
};

class Propagator {
 public:
  Propagator(const RigidBodyModel& m, const BodyState& s0, const StepConfig& cfg);

  /// Advances to time t ≥ time() and returns the state there. Fixed-step methods
  /// split [time(), t] into ⌈Δ/dt⌉ equal steps (≤ dt), so samples land exactly;
  /// rk45 uses dense output; `exact` on a torque-free body evaluates the closed
  /// form at t (no accumulated error). Throws Diverged with time, step, body and method.
  const BodyState& advance_to(double t);
  /// Advances by exactly n steps of dt.
  const BodyState& advance_steps(long n);

  double time() const { return t_; }
  long steps() const { return steps_; }
  const BodyState& state() const { return s_; }
  const RigidBodyModel& model() const { return *m_; }

 private:
  void do_step(double h);
  void check(double h);

  const RigidBodyModel* m_;
  StepConfig cfg_;
  BodyState s0_, s_;
  double t_ = 0, e0_ = 0;
  long steps_ = 0;
  bool torque_free_;
  std::optional<FreeRotationExact> exact_;
  std::unique_ptr<Rk45> rk45_;
};

}  // namespace tumble
