// Tuned kernels of body_frame.hpp, kept apart from the plain forms.
//
// Bit-exactness contract: for a torque-free body, tuned::rk4_body_free(m, s, h)
// returns the same bits as rk4_body_reference(m, s, t, h) for every finite
// input, except that a zero P keeps its sign (the reference adds +0 to it).
// It holds because every double operation below is the one the reference's
// Eigen expressions perform, in the same order, with -ffp-contract=off (no
// fused multiply-add): only dead work (P' = 0) is dropped and the stage
// vectors are kept in scalars so the four stages form one unpacked chain.
// tests/core/reference_kernels_test.cpp holds them equal.
#pragma once

#include <array>

#include "core/body_frame.hpp"

namespace tumble::tuned {

/// (q, Π) as scalars: qx, qy, qz, qw, Πx, Πy, Πz.
using Rot7 = std::array<double, 7>;

/// Rate of (q, Π) for a torque-free body: q' = q ⊗ (0, ½ ω), Π' = Π × ω,
/// ω = I⁻¹ Π. `ih` = ½ I⁻¹ (exact halving, so ½ω = ih ∘ Π bit for bit).
[[gnu::always_inline]] inline Rot7 rot_rate(const double inv[3], const double ih[3], const Rot7& y) {
  const double px = y[4], py = y[5], pz = y[6];
  const double wx = inv[0] * px, wy = inv[1] * py, wz = inv[2] * pz;
  const double hx = ih[0] * px, hy = ih[1] * py, hz = ih[2] * pz;
  const double x = y[0], yy = y[1], z = y[2], w = y[3];
  return {w * hx + (yy * hz - z * hy), w * hy + (z * hx - x * hz), w * hz + (x * hy - yy * hx),
          -((x * hx + yy * hy) + z * hz), py * wz - pz * wy, pz * wx - px * wz, px * wy - py * wx};
}

[[gnu::always_inline]] inline Rot7 axpy7(const Rot7& a, double t, const Rot7& k) {
  return {a[0] + t * k[0], a[1] + t * k[1], a[2] + t * k[2], a[3] + t * k[3],
          a[4] + t * k[4], a[5] + t * k[5], a[6] + t * k[6]};
}

inline BodyState rk4_body_free(const RigidBodyModel& m, const BodyState& s, double h) {
  const double ha = h * 0.5, b1 = h * (1.0 / 6), b2 = h * (1.0 / 3);
  const double inv[3] = {m.inv_inertia.x(), m.inv_inertia.y(), m.inv_inertia.z()};
  const double ih[3] = {0.5 * inv[0], 0.5 * inv[1], 0.5 * inv[2]};
  const Eigen::Vector3d pi = s.q.conjugate() * s.L;
  const Rot7 y0{s.q.x(), s.q.y(), s.q.z(), s.q.w(), pi.x(), pi.y(), pi.z()};
  const Rot7 k1 = rot_rate(inv, ih, y0);
  const Rot7 k2 = rot_rate(inv, ih, axpy7(y0, ha, k1));
  const Rot7 k3 = rot_rate(inv, ih, axpy7(y0, ha, k2));
  const Rot7 k4 = rot_rate(inv, ih, axpy7(y0, h, k3));
  const Rot7 y = axpy7(axpy7(axpy7(axpy7(y0, b1, k1), b2, k2), b2, k3), b1, k4);
  const Eigen::Vector3d v = s.P / m.mass;
  BodyState out;
  out.c = (((s.c + b1 * v) + b2 * v) + b2 * v) + b1 * v;
  out.q = Eigen::Quaterniond(y[3], y[0], y[1], y[2]).normalized();
  out.P = s.P;
  out.L = out.q * Eigen::Vector3d(y[4], y[5], y[6]);
  return out;
}

}  // namespace tumble::tuned
