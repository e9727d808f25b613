// Bench problems, fixed-step and adaptive runs, error measures and CPU timing.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/body.hpp"
#include "core/integrator.hpp"

namespace tumble::bench {

/// One test problem: a body, its initial state, a duration and the reference
/// final state (closed form when torque-free, else dop853 at rtol 1e-13).
struct Problem {
  std::string name;         ///< "t_handle", "symmetric_top", "forced"
  std::string description;  ///< one line for summary.md
  RigidBodyModel model;
  BodyState s0;
  double duration = 10;     ///< s
  bool torque_free = true;  ///< no forces at all: the reference is the closed form
  bool peers = false;       ///< also run the peers (forced problems: those that take forces)
  double dt_max = 0.1;      ///< s, largest fixed step swept (h·|ω| ≈ 1)
  BodyState reference;      ///< state at `duration`
  double reference_check = 0;  ///< forced: |dop853(1e-13) - exact| on the T-handle, rad
};

/// Principal moments (1, 2, 3) kg·m², ω_body = (0.01, 10, 0.01) rad/s, 10 s.
Problem t_handle_problem();
/// Principal moments (2, 2, 4) kg·m², ω_body = (3, 1, 5) rad/s, 10 s: torque-free symmetric top.
Problem symmetric_top_problem();
/// T-handle under gravity g = (0, 0, -9.81) m/s² plus a body-fixed 2 N force at (1, 0, 0) m.
Problem forced_problem();
/// Three more forced scenes with forces and damping: a thruster
/// (gravity, body-fixed force, body torque), a damped tumbler (gravity, linear
/// and angular damping) and a torqued, damped symmetric top.
std::vector<Problem> scene_problems();
/// The T-handle, the symmetric top, the forced T-handle, then scene_problems().
std::vector<Problem> all_problems();
/// A user's body (from a scene) over `duration` (s): the reference is the closed
/// form when it has no forces, else dop853 at rtol 1e-13; with the peers that run it.
Problem body_problem(const std::string& name, const RigidBodyModel& m, const BodyState& s0, double duration);

/// A body with principal moments `I` (kg·m²), unit mass, identity principal frame.
RigidBodyModel diagonal_model(const std::string& name, const Eigen::Vector3d& I, const ForceSet& f = {});
/// State at rest at the origin with body-frame ω (rad/s).
BodyState spinning_state(const RigidBodyModel& m, const Eigen::Vector3d& omega_body);

/// Errors of a final state against the reference: orientation angle (rad) and
/// relative total energy |E - E_ref| / |E_ref|.
struct Errors {
  double angle = 0;
  double energy = 0;
};
Errors errors(const Problem& p, const BodyState& s);

/// n = round(T/dt) fixed steps of h = T/n. Non-finite states stop early.
BodyState run_fixed(Method method, const RigidBodyModel& m, const BodyState& s0, double T, double dt);
/// An adaptive pair (rk45, dop853) to T with atol = rtol, its last step ending on T.
BodyState run_adaptive(Method method, const RigidBodyModel& m, const BodyState& s0, double T, double rtol);
/// The forced problems' reference: dop853 at rtol kReferenceRtol.
inline constexpr double kReferenceRtol = 1e-13;
BodyState reference_run(const RigidBodyModel& m, const BodyState& s0, double T);

/// Median CPU seconds (this thread) per call of `fn`; each timed batch repeats
/// `fn` until it spans at least `min_batch_s`.
double median_cpu_seconds(const std::function<void()>& fn, double min_batch_s, int repeats);

/// Thread CPU time, s.
double thread_cpu_seconds();

/// Log-spaced values from `hi` down to `lo`, `per_decade` per factor of 10.
std::vector<double> log_sweep(double hi, double lo, int per_decade);
/// The values 10^(k/per_decade) in [lo, hi], largest first: sweeps over
/// different ranges share their points.
std::vector<double> decade_grid(double hi, double lo, int per_decade);

/// Sign changes of the intermediate-axis momentum Π₂ (the Dzhanibekov flips).
struct FlipCounter {
  int count = 0;
  double first_time = -1;  ///< s; -1 when none
  double last_sign = 0;
  void observe(double pi2, double t);
};

}  // namespace tumble::bench
