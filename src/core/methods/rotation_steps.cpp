#include "core/methods/rotation_steps.hpp"

#include <cmath>

#include <Eigen/LU>

#include "core/dynamics.hpp"
#include "core/quaternion.hpp"
#include "core/methods/splitting_kernel.hpp"

namespace tumble {

void free_rotation_splitting(const RigidBodyModel& m, const Eigen::Vector3d& L, Eigen::Quaterniond& q, double h,
                             int order) {
  const kernel::Quat o =
      kernel::splitting_rotation_ordered(order, {q.w(), q.x(), q.y(), q.z()}, L.data(), m.inv_inertia.data(), h);
  q = Eigen::Quaterniond(o.w, o.x, o.y, o.z);
}

void free_rotation_splitting(const RigidBodyModel& m, const Eigen::Vector3d& L,
                             Eigen::Quaterniond& q, double h) {
  free_rotation_splitting(m, L, q, h, kernel::split_order(m.inv_inertia.data()));
}

void free_rotation_splitting_reference(const RigidBodyModel& m, const Eigen::Vector3d& L,
                                       Eigen::Quaterniond& q, double h, int order) {
  Eigen::Vector3d pi = q.conjugate() * L;
  Eigen::Quaterniond r = Eigen::Quaterniond::Identity();
  const int* abc = kernel::kSplitAxes[order];
  const int axes[5] = {abc[0], abc[1], abc[2], abc[1], abc[0]};
  const double taus[5] = {0.5 * h, 0.5 * h, h, 0.5 * h, 0.5 * h};
  for (int n = 0; n < 5; ++n) {
    const int i = axes[n], j = (i + 1) % 3, k = (i + 2) % 3;
    const double half = 0.5 * taus[n] * pi[i] * m.inv_inertia[i];
    const double ch = std::cos(half), sh = std::sin(half);
    const double c = ch * ch - sh * sh, s = 2 * ch * sh;
    const double pj = pi[j], pk = pi[k];
    pi[j] = c * pj + s * pk;
    pi[k] = -s * pj + c * pk;
    r = r * axis_rotation(i, 2 * half);
  }
  q = (q * r).normalized();
}

void free_rotation_midpoint(const RigidBodyModel& m, const Eigen::Vector3d& L,
                            Eigen::Quaterniond& q, double h) {
  const Eigen::Vector3d& inv_inertia = m.inv_inertia;
  const Eigen::Vector3d pi0 = q.conjugate() * L;
  // Πm = Π₀ + (h/2) Πm × I⁻¹Πm, solved by Newton's method: the fixed-point
  // iteration only contracts for h|ω| < ~1 and returns NaN beyond. With
  // W = I⁻¹, the Jacobian of F(a) = a - Π₀ - (h/2) a × Wa is
  // 1 - (h/2)([a]× W - [Wa]×).
  auto skew = [](const Eigen::Vector3d& v) {
    Eigen::Matrix3d k;
    k << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
    return k;
  };
  Eigen::Vector3d pim = pi0;
  const double tol = 4e-16 * pi0.norm();
  for (int it = 0; it < 50; ++it) {
    const Eigen::Vector3d wa = inv_inertia.cwiseProduct(pim);
    const Eigen::Vector3d f = pim - pi0 - 0.5 * h * pim.cross(wa);
    const Eigen::Matrix3d jac =
        Eigen::Matrix3d::Identity() - 0.5 * h * (skew(pim) * inv_inertia.asDiagonal() - skew(wa));
    const Eigen::Vector3d delta = jac.partialPivLu().solve(f);
    pim -= delta;
    if (delta.lpNorm<Eigen::Infinity>() <= tol) break;
  }
  const Eigen::Vector3d half = 0.5 * h * inv_inertia.cwiseProduct(pim);
  q = (q * Eigen::Quaterniond(1.0, half.x(), half.y(), half.z()).normalized()).normalized();
}

namespace {
// Template so the per-step maps inline (no call through a pointer).
template <class Rotate>
BodyState strang(const RigidBodyModel& m, const BodyState& s, double t, double h, Rotate&& rotate) {
  const bool forced = !m.forces.empty();
  BodyState x = forced ? kick(m, s, t, 0.5 * h) : s;
  x.c += h * x.P / m.mass;
  rotate(m, x.L, x.q, h);
  return forced ? kick(m, x, t + h, 0.5 * h) : x;
}
}  // namespace

BodyState strang_step(const RigidBodyModel& m, const BodyState& s, double t, double h,
                      FreeRotationMap rotate) {
  return strang(m, s, t, h, rotate);
}

BodyState splitting_step(const RigidBodyModel& m, const BodyState& s, double t, double h) {
  return splitting_step_ordered(m, s, t, h, kernel::split_order(m.inv_inertia.data()));
}

BodyState splitting_step_ordered(const RigidBodyModel& m, const BodyState& s, double t, double h, int order) {
  return strang(m, s, t, h, [order](const RigidBodyModel& b, const Eigen::Vector3d& L, Eigen::Quaterniond& q, double tau) {
    free_rotation_splitting(b, L, q, tau, order);
  });
}

BodyState splitting4_step(const RigidBodyModel& m, const BodyState& s, double t, double h) {
  const double cbrt2 = std::cbrt(2.0);
  const double w1 = 1.0 / (2.0 - cbrt2), w0 = -cbrt2 * w1;
  const int order = kernel::split_order4(m.inv_inertia.data());
  const auto rotate = [order](const RigidBodyModel& b, const Eigen::Vector3d& L, Eigen::Quaterniond& q, double tau) {
    free_rotation_splitting(b, L, q, tau, order);
  };
  BodyState x = strang(m, s, t, w1 * h, rotate);
  x = strang(m, x, t + w1 * h, w0 * h, rotate);
  return strang(m, x, t + (w1 + w0) * h, w1 * h, rotate);
}

BodyState implicit_midpoint_step(const RigidBodyModel& m, const BodyState& s, double t, double h) {
  return strang_step(m, s, t, h, free_rotation_midpoint);
}

BodyState semi_implicit_euler_step(const RigidBodyModel& m, const BodyState& s, double t, double h) {
  BodyState x = s;
  if (!m.forces.empty()) {
    const Wrench w = wrench(m, s, t);
    x.P += h * w.force;
    x.L += h * w.torque;
  }
  x.c += h * x.P / m.mass;
  const Eigen::Vector3d omega = s.q * m.inv_inertia.cwiseProduct(s.q.conjugate() * x.L);
  x.q = (quat_exp(h * omega) * s.q).normalized();
  return x;
}

}  // namespace tumble
