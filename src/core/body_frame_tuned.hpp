// Tuned kernels of body_frame.hpp, kept apart from the plain forms.
//
// Bit-exactness contract: for a torque-free body, tuned::rk4_coords_free(m, x, h)
// and tuned::rk4_body_free(m, s, h) return the same bits as
// rk4_coords_reference(m, x, t, h) and rk4_body_reference(m, s, t, h) for every
// finite input, except that a zero P keeps its sign (the reference adds +0 to it).
// It holds because every double operation below is the one the reference's
// Eigen expressions perform, in the same order, with -ffp-contract=off (no
// fused multiply-add): only dead work (P' = 0) is dropped, and the stage
// vectors and the two rotations (Eigen's q * v) are kept in scalars, so the
// step is one unpacked chain (measured figures: docs/methods.md's generated speed
// table, scripts/gen_method_costs.sh).
// tests/core/reference_kernels_test.cpp holds them equal.
#pragma once

#include <array>

#include "core/body_frame.hpp"
#include "core/quaternion.hpp"

namespace tumble::tuned {

/// (q, Π) as scalars: qx, qy, qz, qw, Πx, Πy, Πz.
using Rot7 = std::array<double, 7>;

/// Rate of (q, Π) for a torque-free body with q's part doubled: (q ⊗ (0, ω),
/// Π × ω), ω = I⁻¹ Π, i.e. (2 q', Π'). The reference forms q' = q ⊗ (0, ½ω)
/// with ½ω = (½ I⁻¹) Π; every q-term here is exactly twice its term there
/// (scaling by 2 is exact), so with the ½ folded into q's step coefficients
/// (rk4_rot) the bits are the reference's, and 3 of each stage's 24 products
/// are gone.
[[gnu::always_inline]] inline Rot7 rot_rate2(const double inv[3], const Rot7& y) {
  const double px = y[4], py = y[5], pz = y[6];
  const double wx = inv[0] * px, wy = inv[1] * py, wz = inv[2] * pz;
  const double x = y[0], yy = y[1], z = y[2], w = y[3];
  return {w * wx + (yy * wz - z * wy), w * wy + (z * wx - x * wz), w * wz + (x * wy - yy * wx),
          -((x * wx + yy * wy) + z * wz), py * wz - pz * wy, pz * wx - px * wz, px * wy - py * wx};
}

/// a + t k with q's part scaled by tq and Π's by tp.
[[gnu::always_inline]] inline Rot7 axpy7(const Rot7& a, double tq, double tp, const Rot7& k) {
  return {a[0] + tq * k[0], a[1] + tq * k[1], a[2] + tq * k[2], a[3] + tq * k[3],
          a[4] + tp * k[4], a[5] + tp * k[5], a[6] + tp * k[6]};
}

/// Compensated x + Δ (BodyCoords::lost_pi): d = Δ − lost, x' = x + d, lost' = (x' − x) − d.
[[gnu::always_inline]] inline void kahan_add(double x, double delta, double& lost, double& out) {
  const double d = delta - lost;
  out = x + d;
  lost = (out - x) - d;
}

/// RK4 on (q, Π) for a torque-free body, q not renormalised; y = (q, Π),
/// lost = Π's round-off carry (BodyCoords::lost_pi), in and out.
[[gnu::always_inline]] inline Rot7 rk4_rot(const double inv[3], double h, const Rot7& y0, double lost[3]) {
  const double ha = h * 0.5, b1 = h * (1.0 / 6), b2 = h * (1.0 / 3);
  // q's coefficients carry the ½ of q' = ½ q ⊗ (0, ω): (½ t) k = t (½ k) exactly.
  const double haq = 0.5 * ha, hq = 0.5 * h, b1q = 0.5 * b1, b2q = 0.5 * b2;
  const Rot7 k1 = rot_rate2(inv, y0);
  const Rot7 k2 = rot_rate2(inv, axpy7(y0, haq, ha, k1));
  const Rot7 k3 = rot_rate2(inv, axpy7(y0, haq, ha, k2));
  const Rot7 k4 = rot_rate2(inv, axpy7(y0, hq, h, k3));
  Rot7 y;
  for (int j = 0; j < 4; ++j) y[j] = y0[j] + (((b1q * k1[j] + b2q * k2[j]) + b2q * k3[j]) + b1q * k4[j]);
  for (int j = 4; j < 7; ++j)
    kahan_add(y0[j], ((b1 * k1[j] + b2 * k2[j]) + b2 * k3[j]) + b1 * k4[j], lost[j - 4], y[j]);
  return y;
}

/// c after four RK stages of c' = P/M (P' = 0: P stays), the reference's sums.
[[gnu::always_inline]] inline Eigen::Vector3d drift4(const RigidBodyModel& m, const Eigen::Vector3d& c,
                                                     const Eigen::Vector3d& P, double h) {
  const double b1 = h * (1.0 / 6), b2 = h * (1.0 / 3);
  const Eigen::Vector3d v = P / m.mass;
  return c + (((b1 * v + b2 * v) + b2 * v) + b1 * v);
}

/// rk4_coords_free in place: x ← one step of h (s). In place, so a run's
/// carried coordinates are not copied in and out each step.
[[gnu::always_inline]] inline void rk4_coords_free_inplace(const RigidBodyModel& m, BodyCoords& x, double h) {
  const double inv[3] = {m.inv_inertia.x(), m.inv_inertia.y(), m.inv_inertia.z()};
  const Rot7 y = rk4_rot(inv, h, {x.q.x(), x.q.y(), x.q.z(), x.q.w(), x.pi.x(), x.pi.y(), x.pi.z()}, x.lost_pi.data());
  x.c = drift4(m, x.c, x.P, h);
  x.q = Eigen::Quaterniond(y[3], y[0], y[1], y[2]);
  x.pi = {y[4], y[5], y[6]};
}

inline BodyCoords rk4_coords_free(const RigidBodyModel& m, const BodyCoords& x, double h) {
  BodyCoords out = x;
  rk4_coords_free_inplace(m, out, h);
  return out;
}

inline BodyState rk4_body_free(const RigidBodyModel& m, const BodyState& s, double h) {
  BodyCoords x;
  x.c = s.c;
  x.q = s.q;
  x.P = s.P;
  rotate(-s.q.x(), -s.q.y(), -s.q.z(), s.q.w(), s.L.data(), x.pi.data());  // Π = q̄ L
  const BodyCoords y = rk4_coords_free(m, x, h);
  BodyState out;
  out.c = y.c;
  out.q = unit_quaternion(y.q.x(), y.q.y(), y.q.z(), y.q.w());
  out.P = s.P;
  rotate(out.q.x(), out.q.y(), out.q.z(), out.q.w(), y.pi.data(), out.L.data());  // L = q Π
  return out;
}

}  // namespace tumble::tuned
