// Adaptive Dormand–Prince 5(4) (Dormand & Prince, J. Comput. Appl. Math. 6, 1980;
// Hairer–Nørsett–Wanner I, §II.4–5 for step control, dense output and the
// initial step) on the seed's ODE in Euler's coordinates (c, q, P, Π = q̄ L),
// as rk4 (body_frame.hpp).
#pragma once

#include <limits>

#include "core/body.hpp"

namespace tumble {

struct Rk45Options {
  double rtol = 1e-9;   ///< relative tolerance per component
  double atol = 1e-12;  ///< absolute tolerance per component (SI units of the component)
  double h_max = std::numeric_limits<double>::infinity();  ///< s
  long max_steps = 50'000'000;
};

/// Integrates one body from t0; `advance_to` returns the state at any later time
/// by continuous (dense) output inside the accepted step, so sampling never
/// shortens steps.
class Rk45 {
 public:
  Rk45(const RigidBodyModel& m, const BodyState& s0, double t0, const Rk45Options& opt);
  BodyState advance_to(double t);
  long accepted() const { return accepted_; }
  long rejected() const { return rejected_; }

  using Vec = Eigen::Matrix<double, 13, 1>;  // (c, q xyzw, P, Π)

 private:
  Vec f(double t, const Vec& y) const;
  void take_step();
  double initial_step() const;

  const RigidBodyModel* m_;
  Rk45Options opt_;
  double t_, h_;
  Vec y_, k1_;
  // Last accepted step [t_prev_, t_] and its dense-output coefficients.
  double t_prev_;
  Vec y_prev_;
  Eigen::Matrix<double, 13, 5> dense_;
  long accepted_ = 0, rejected_ = 0;
};

BodyState rk45_fixed_step(const RigidBodyModel& m, const BodyState& s, double t, double h);

}  // namespace tumble
