#include "core/fixed_stepper.hpp"

#include <cmath>

#include "core/dynamics.hpp"
#include "core/quaternion.hpp"
#include "core/methods/splitting_kernel.hpp"

namespace tumble {

FixedStepper::FixedStepper(Method method, const RigidBodyModel& m, const BodyState& s0)
    : m_(&m), info_(&method_info(method)), s_(s0) {
  if (info_->coords_step) coords_ = to_body_coords(s0);
  if (info_->ordered_step) order_ = kernel::split_order_for_start(m.inv_inertia.data(), momentum_body(s0).data());
}

BodyState FixedStepper::seed_step(const BodyState& s, double t, double h) const {
  return order_ >= 0 ? info_->ordered_step(*m_, s, t, h, order_) : tumble::step(info_->method, *m_, s, t, h);
}

void FixedStepper::step(double t, double h) {
  if (!coords_) {
    const Eigen::Quaterniond prev = s_.q;
    s_ = seed_step(s_, t, h);
    s_.q = same_hemisphere(s_.q, prev);
    return;
  }
  BodyCoords& x = *coords_;
  const Eigen::Quaterniond prev = x.q;
  info_->coords_step(*m_, x, t, h);
  if (x.q.dot(prev) < 0) x.q.coeffs() = -x.q.coeffs();  // q and -q step to negated q, same Π: no change
  // The step leaves |q| alone (body_frame.hpp); renormalise once it drifts.
  // A blow-up still shows: in Π's energy, or as a non-finite q.
  const double n = x.q.squaredNorm();
  if (std::abs(n - 1.0) > 1e-12 && std::isfinite(n)) x.q = unit_quaternion(x.q.x(), x.q.y(), x.q.z(), x.q.w());
}

BodyState FixedStepper::state() const { return coords_ ? state_of(*coords_) : s_; }

BodyState FixedStepper::peek(double t, double h) const {
  BodyState s;
  if (coords_) {
    BodyCoords x = *coords_;
    info_->coords_step(*m_, x, t, h);
    s = state_of(x);
  } else {
    s = seed_step(s_, t, h);
  }
  const Eigen::Quaterniond ref = coords_ ? coords_->q : s_.q;
  s.q = same_hemisphere(s.q, ref);
  return s;
}

BodyState integrate_fixed(Method method, const RigidBodyModel& m, const BodyState& s0, double t0, double h, long n) {
  FixedStepper s(method, m, s0);
  for (long i = 0; i < n; ++i) s.step(t0 + static_cast<double>(i) * h, h);
  return s.state();
}

}  // namespace tumble
