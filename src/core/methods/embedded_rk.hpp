// Adaptive embedded Runge–Kutta pairs on the seed's ODE in Euler's coordinates
// (q, Π = q̄ L; c, P when forces act), as rk4 (body_frame.hpp):
//  - `rk45`: Dormand–Prince 5(4) (Dormand & Prince, J. Comput. Appl. Math. 6,
//    1980), FSAL, continuous extension of HNW I §II.6 (CONTD5);
//  - `dop853`: Dormand–Prince 8(5,3) with Hairer's coefficients and 7th-order
//    dense output (HNW I §II.10, code DOP853).
// Both step with local extrapolation and a PI controller (Gustafsson, BIT 31,
// 1991; HNW II §IV.2; Hairer's codes' β = 0.04), which makes the end error
// proportional to the tolerance (Stetter; Higham, SIAM J. Numer. Anal. 27,
// 1990). The error norm is what users measure: the largest over the groups of
// orientation angle 2|δq| / (rtol + atol) and |δΠ| / (atol |Π₀| + rtol |Π|),
// and likewise for c (radius of gyration) and P when forces act. rtol asks for
// the error at the end of a run, not per step: each pair aims its steps at
// rtol / kGlobalPerLocal, the ratio of end error to local tolerance measured on
// the bench problems (so the delivered error is within 10× of rtol there).
#pragma once

#include <limits>
#include <memory>

#include "core/body.hpp"

namespace tumble {

struct AdaptiveOptions {
  double rtol = 1e-9;   ///< relative tolerance (orientation: rad)
  double atol = 1e-12;  ///< absolute floor, as a fraction of the body's scales (|Π₀|, radius of gyration)
  double h_max = std::numeric_limits<double>::infinity();   ///< s
  double t_stop = std::numeric_limits<double>::infinity();  ///< s: no step goes past it (a run's end)
  long max_steps = 50'000'000;
};

/// One body integrated from t0; `advance_to` returns the state at any later
/// time by dense output inside the accepted step, so sampling never shortens
/// steps (and costs no evaluation until a step holds a sample).
class AdaptiveIntegrator {
 public:
  virtual ~AdaptiveIntegrator() = default;
  virtual BodyState advance_to(double t) = 0;  ///< t non-decreasing from call to call
  virtual long accepted() const = 0;
  virtual long rejected() const = 0;
  virtual long evaluations() const = 0;  ///< right-hand side evaluations so far
  virtual double time() const = 0;       ///< s, where the last accepted step ended (at or past the last t asked)
  virtual double next_step() const = 0;  ///< s, the step the controller will try next
};

std::unique_ptr<AdaptiveIntegrator> make_rk45(const RigidBodyModel& m, const BodyState& s0, double t0,
                                              const AdaptiveOptions& opt);
std::unique_ptr<AdaptiveIntegrator> make_dop853(const RigidBodyModel& m, const BodyState& s0, double t0,
                                                const AdaptiveOptions& opt);

/// One uncontrolled step of each pair's high-order solution (convergence studies).
BodyState rk45_fixed_step(const RigidBodyModel& m, const BodyState& s, double t, double h);
BodyState dop853_fixed_step(const RigidBodyModel& m, const BodyState& s, double t, double h);

}  // namespace tumble
