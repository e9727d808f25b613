// `method = "auto"` with a tolerance: pick the cheapest method (and its step)
// whose error at the end of the run stays within the tolerance, from error
// measured on the body itself and per-step costs measured by the microbench.
#pragma once

#include <string>
#include <vector>

#include "core/body.hpp"
#include "core/integrator.hpp"
#include "core/propagator.hpp"

namespace tumble {

/// What a run asks of auto.
struct ChoiceRequest {
  double duration = 10;         ///< s, the run's length
  double sample_interval = 0;   ///< s between samples (frames): one partial step each; 0 = none
  double tolerance = 1e-6;      ///< largest end error, rad (see end_state_error)
  bool prune = true;            ///< false: measure every candidate (tests)
};

/// One candidate's measured error model and predicted cost.
struct MethodEstimate {
  Method method = Method::splitting;
  bool usable = false;          ///< its error model was verified on this body
  StepConfig config;            ///< step (adaptive pairs: rtol, atol) that meets the tolerance
  double steps = 0;             ///< predicted steps of the run
  double error = 0;             ///< predicted end error, rad
  double cost_s = 0;            ///< predicted CPU s: steps × step_cost_ns
  double observed_order = 0;    ///< from the pilot (adaptive pairs: 0)
  std::string note;             ///< why it is not usable
};

struct MethodChoice {
  StepConfig config;
  double error = 0;             ///< predicted end error, rad
  double cost_s = 0;            ///< predicted CPU s
  std::string reason;           ///< one line for the user: what was picked and why
  std::vector<MethodEstimate> candidates;  ///< empty when no pilot ran (torque-free)
};

/// Error of state `a` against `b` as one number: the larger of the rotation
/// angle between them (rad) and the centre-of-mass offset in radii of gyration
/// sqrt((I1+I2+I3)/(2M)) (a shift of one radius counts as one radian).
double end_state_error(const RigidBodyModel& m, const BodyState& a, const BodyState& b);

/// CPU time of one step (ns) on a body like `m`, measured by
/// `tumble_microbench --benchmark_filter='BM_Step/'`: the torque-free T-handle,
/// the forced T-handle, or (forced, two equal moments) the torqued symmetric top.
/// Used as relative weights, so the choice does not depend on the load of the
/// machine it runs on.
double step_cost_ns(Method method, const RigidBodyModel& m);

/// The pilot's order window: whether successive differences shrinking by
/// 2^observed show an order-p method in its asymptotic range, |observed - p|
/// <= 0.4 (NaN: no). Wider, a pilot still short of it (an order-2 method
/// showing 1.5) would be extrapolated as if it were there, and miss the tolerance.
bool order_seen(double observed, int p);

/// `method = "auto"`'s first rule, the one place it is decided: a torque-free
/// body needs no measurement, as the closed form (`exact`) is exact for it.
bool auto_takes_closed_form(const RigidBodyModel& m);

/// `method = "auto"` without a tolerance: `exact` for a torque-free body, else
/// `asked` as it is (dt, rtol, atol, and StepConfig's default method unless the
/// caller set another), with the one-line reason. No candidates are measured.
MethodChoice auto_without_tolerance(const RigidBodyModel& m, const StepConfig& asked);

/// Torque-free bodies get `exact` (auto_takes_closed_form: the closed form, error at round-off). Other
/// bodies, with `prune` (scenes): `exact` when no force torques the body and
/// its pilot ladder qualifies, else the highest-order adaptive pair (dop853) at
/// rtol = atol = tolerance / 10 with no pilot (the pairs' rtol asks for the end
/// error; embedded_rk.hpp); on a torqued axisymmetric body that pair is priced
/// and weighed against `exact` with kicks, probed on the first 1/8 of the run.
/// Without `prune` every candidate is measured: each
/// fixed-step method runs the whole duration at N, 2N, 4N, … steps; the
/// differences of successive end states give its error (Richardson: e(h) ≈
/// d/(2^p - 1) once two successive ratios match the order p), which fixes the
/// step that meets half the tolerance (0.2 s of predicted CPU per ladder); the
/// adaptive pairs are priced on the first 1/32 of the run. The cheapest usable
/// candidate wins. Throws InputError when none is.
MethodChoice choose_method(const RigidBodyModel& m, const BodyState& s0, const ChoiceRequest& req);

}  // namespace tumble
