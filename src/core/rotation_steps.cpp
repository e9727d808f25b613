#include "core/rotation_steps.hpp"

#include <cmath>

#include <Eigen/LU>

#include "core/dynamics.hpp"
#include "core/quaternion.hpp"

namespace tumble {

namespace {

// Flow of Tᵢ over τ: the body turns by θ = τ Πᵢ/Iᵢ about axis i, so Π (body
// components) turns by -θ. Returns the half-angle rotation for q; one sincos
// serves both (cos θ = c² - s², sin θ = 2cs).
inline Eigen::Quaterniond axis_flow(int i, double inv_i, double tau, Eigen::Vector3d& pi) {
  const double half = 0.5 * tau * pi[i] * inv_i;
  const double ch = std::cos(half), sh = std::sin(half);
  const double c = ch * ch - sh * sh, s = 2 * ch * sh;
  const int j = (i + 1) % 3, k = (i + 2) % 3;
  const double pj = pi[j], pk = pi[k];
  pi[j] = c * pj + s * pk;
  pi[k] = -s * pj + c * pk;
  Eigen::Quaterniond r(ch, 0, 0, 0);
  r.vec()[i] = sh;
  return r;
}

}  // namespace

void free_rotation_splitting(const RigidBodyModel& m, const Eigen::Vector3d& L,
                             Eigen::Quaterniond& q, double h) {
  const Eigen::Vector3d& inv_inertia = m.inv_inertia;
  Eigen::Vector3d pi = q.conjugate() * L;
  Eigen::Quaterniond r = axis_flow(0, inv_inertia[0], 0.5 * h, pi);
  r = r * axis_flow(1, inv_inertia[1], 0.5 * h, pi);
  r = r * axis_flow(2, inv_inertia[2], h, pi);
  r = r * axis_flow(1, inv_inertia[1], 0.5 * h, pi);
  r = r * axis_flow(0, inv_inertia[0], 0.5 * h, pi);
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

BodyState strang_step(const RigidBodyModel& m, const BodyState& s, double t, double h,
                      FreeRotationMap rotate) {
  const bool forced = !m.forces.empty();
  BodyState x = forced ? kick(m, s, t, 0.5 * h) : s;
  x.c += h * x.P / m.mass;
  rotate(m, x.L, x.q, h);
  return forced ? kick(m, x, t + h, 0.5 * h) : x;
}

BodyState splitting_step(const RigidBodyModel& m, const BodyState& s, double t, double h) {
  return strang_step(m, s, t, h, free_rotation_splitting);
}

BodyState splitting4_step(const RigidBodyModel& m, const BodyState& s, double t, double h) {
  const double cbrt2 = std::cbrt(2.0);
  const double w1 = 1.0 / (2.0 - cbrt2), w0 = -cbrt2 * w1;
  BodyState x = splitting_step(m, s, t, w1 * h);
  x = splitting_step(m, x, t + w1 * h, w0 * h);
  return splitting_step(m, x, t + (w1 + w0) * h, w1 * h);
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
