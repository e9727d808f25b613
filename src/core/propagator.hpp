// Advances one body through a run, sample time by sample time, with the
// numeric-failure guard.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "core/body.hpp"
#include "core/body_frame.hpp"
#include "core/fixed_stepper.hpp"
#include "core/methods/free_rotation_exact.hpp"
#include "core/integrator.hpp"
#include "core/methods/embedded_rk.hpp"

namespace tumble {

/// How a body is stepped: the one config of the core, the scenes' [simulation]
/// and the CLI. Its default method is the scenes' default: `splitting` keeps
/// |L| exactly and the energy without drift at any dt, forces or not.
struct StepConfig {
  Method method = Method::splitting;
  double dt = 1e-3;         ///< s, fixed step (adaptive pairs: unused)
  double rtol = 1e-9;       ///< adaptive pairs (rk45, dop853) only
  double atol = 1e-12;      ///< adaptive pairs only (a fraction of the body's scales)
};

/// Most steps one run may take (duration / dt): scenes reject more, and
/// `method = "auto"` never picks more.
inline constexpr double kMaxRunSteps = 1e9;

/// A warning when dt is too coarse for the method to follow the body's initial
/// rotation: dt·(|ω| + damping rates) above MethodInfo::max_turn_per_step.
/// Empty when fine (and for rk45 and the closed form, which pick their own steps).
std::optional<std::string> coarse_step_warning(const RigidBodyModel& m, const BodyState& s0, const StepConfig& cfg);

class Propagator {
 public:
  Propagator(const RigidBodyModel& m, const BodyState& s0, const StepConfig& cfg);

  /// Advances to time t ≥ time() and returns the state there. Fixed-step
  /// methods step on the grid t_n = n·dt whatever the sample times are; a
  /// sample between grid points is one partial step from the last grid state,
  /// never fed back, so the trajectory does not depend on fps, --every or
  /// --frames. the adaptive pairs use dense output; `exact` on a torque-free body evaluates
  /// the closed form at t. Throws Diverged with time, step, body and method.
  const BodyState& advance_to(double t);
  /// Advances by exactly n steps of dt (fixed-step methods: to the grid point
  /// n steps on from the last one reached).
  const BodyState& advance_steps(long n);

  double time() const { return t_; }
  /// Steps taken on the grid (adaptive pairs: accepted steps; closed form: evaluations).
  long steps() const { return steps_; }
  const BodyState& state() const { return s_; }
  const RigidBodyModel& model() const { return *m_; }
  const StepConfig& config() const { return cfg_; }

 private:
  void grid_step();
  void check(const BodyState& s, double t, double h);
  /// check() for a torque-free body carried in Euler's coordinates: the same
  /// test (E is an invariant) without forming the seed's state every step. P
  /// stays bit for bit (P' = 0), so only the rotational energy ½ Π·I⁻¹Π can
  /// grow; FixedStepper keeps |q| = 1, so q is tested for finiteness only.
  void check_free(const BodyCoords& x, double t, double h);
  /// The same for a torque-free body on the seed's state: E = ½ Π·I⁻¹Π with
  /// Π = q̄ L, plus |q| = 1 (a q whose norm overflowed normalises to a finite 0).
  void check_free(const BodyState& s, double t, double h);
  /// Whether Π's energy erot (J) stays within the blow-up bound of its start.
  bool free_energy_held(double erot) const;
  [[noreturn]] void diverged(bool finite, double t, double h) const;

  const RigidBodyModel* m_;
  const MethodInfo* info_;
  StepConfig cfg_;
  BodyState s0_, s_;   // s_: last sample
  FixedStepper grid_;  // the state at t = steps_·dt (fixed-step methods)
  double t_ = 0;
  long steps_ = 0;
  // Energy balance: E − E0 may exceed the work of the driving terms only by round-off.
  double e0_ = 0, erot0_ = 0, scale0_ = 0, work_ = 0, work_abs_ = 0, power_ = 0, power_abs_ = 0;
  std::optional<FreeRotationExact> exact_;
  std::unique_ptr<AdaptiveIntegrator> adaptive_;
};

}  // namespace tumble
