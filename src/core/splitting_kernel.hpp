// The arithmetic of one torque-free `splitting` rotation on plain doubles, shared
// by core's splitting_step and the structure-of-arrays bench kernel so both give
// the same bits. Header-only and call-free on the fast path so loops over many
// bodies vectorise.
#pragma once

#include <cmath>

namespace tumble::kernel {

inline constexpr double kPiOver4 = 0.78539816339744830962;

/// sin and cos for |x| ≤ π/4 (FreeBSD msun k_sin.c / k_cos.c kernels, error
/// < 1 ulp): no range reduction, no branches, no libm call.
[[gnu::always_inline]] inline void sincos_small(double x, double& s, double& c) {
  constexpr double S1 = -1.66666666666666324348e-01, S2 = 8.33333333332248946124e-03,
                   S3 = -1.98412698298579493134e-04, S4 = 2.75573137070700676789e-06,
                   S5 = -2.50507602534068634195e-08, S6 = 1.58969099521155010221e-10;
  constexpr double C1 = 4.16666666666666019037e-02, C2 = -1.38888888888741095749e-03,
                   C3 = 2.48015872894767294178e-05, C4 = -2.75573143513906633035e-07,
                   C5 = 2.08757232129817482790e-09, C6 = -1.13596475577881948265e-11;
  const double z = x * x, w = z * z;
  const double rs = S2 + z * (S3 + z * S4) + z * w * (S5 + z * S6);
  s = x + z * x * (S1 + z * rs);
  const double rc = z * (C1 + z * (C2 + z * C3)) + w * w * (C4 + z * (C5 + z * C6));
  const double hz = 0.5 * z, a = 1.0 - hz;
  c = a + (((1.0 - a) - hz) + z * rc);  // recovers the rounding of 1 - z/2
}

/// sin and cos for any x: the kernel inside ±π/4, libm outside.
inline void sincos_any(double x, double& s, double& c) {
  if (std::abs(x) <= kPiOver4) return sincos_small(x, s, c);
  s = std::sin(x);
  c = std::cos(x);
}

struct Quat {
  double w, x, y, z;
};

/// Hamilton product a ⊗ b.
[[gnu::always_inline]] inline Quat mul(const Quat& a, const Quat& b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y + a.y * b.w + a.z * b.x - a.x * b.z, a.w * b.z + a.z * b.w + a.x * b.y - a.y * b.x};
}

/// a ⊗ (ch + sh eᵢ): the full product with its zero terms dropped (they add
/// exact zeros, so the finite results are the same bits).
template <int I>
[[gnu::always_inline]] inline Quat mul_axis(const Quat& a, double ch, double sh) {
  if constexpr (I == 0) return {a.w * ch - a.x * sh, a.w * sh + a.x * ch, a.y * ch + a.z * sh, a.z * ch - a.y * sh};
  if constexpr (I == 1) return {a.w * ch - a.y * sh, a.x * ch - a.z * sh, a.w * sh + a.y * ch, a.z * ch + a.x * sh};
  if constexpr (I == 2) return {a.w * ch - a.z * sh, a.x * ch + a.y * sh, a.y * ch - a.x * sh, a.w * sh + a.z * ch};
}

/// Flow of Tᵢ = Πᵢ²/(2Iᵢ) over τ: the body turns by θ = τ Πᵢ/Iᵢ about axis i, so
/// Π turns by -θ; r picks up the half-angle rotation. One sincos of θ/2 serves
/// both (cos θ = c² - s², sin θ = 2cs).
template <int I, bool kSmall, bool kFirst>
[[gnu::always_inline]] inline void axis_flow(double inv_i, double tau, double pi[3], Quat& r) {
  const double half = 0.5 * tau * pi[I] * inv_i;
  double sh, ch;
  if constexpr (kSmall) sincos_small(half, sh, ch);
  else sincos_any(half, sh, ch);
  const double c = ch * ch - sh * sh, s = 2 * ch * sh;
  constexpr int J = (I + 1) % 3, K = (I + 2) % 3;
  const double pj = pi[J], pk = pi[K];
  pi[J] = c * pj + s * pk;
  pi[K] = -s * pj + c * pk;
  if constexpr (kFirst) {
    r = {ch, 0, 0, 0};
    (I == 0 ? r.x : I == 1 ? r.y : r.z) = sh;
  } else {
    r = mul_axis<I>(r, ch, sh);
  }
}

/// NO_SQUISH / DLM symmetric splitting 1(h/2) 2(h/2) 3(h) 2(h/2) 1(h/2) of the
/// free rotation: q ← normalise(q ⊗ r) with world L (l) fixed. `kSmall` = the
/// caller guarantees every half angle |hΠᵢ/(4Iᵢ)|, |hΠ₃/(2I₃)| ≤ π/4.
template <bool kSmall>
[[gnu::always_inline]] inline Quat splitting_rotation(const Quat& q, const double l[3], const double inv[3], double h) {
  // Π = q̄ L (Eigen's formula: L + 2w (v × L) + v × 2(v × L) with v = -q.vec).
  const double vx = -q.x, vy = -q.y, vz = -q.z;
  const double ux = 2 * (vy * l[2] - vz * l[1]), uy = 2 * (vz * l[0] - vx * l[2]), uz = 2 * (vx * l[1] - vy * l[0]);
  double pi[3] = {l[0] + q.w * ux + (vy * uz - vz * uy), l[1] + q.w * uy + (vz * ux - vx * uz),
                  l[2] + q.w * uz + (vx * uy - vy * ux)};
  Quat r;
  axis_flow<0, kSmall, true>(inv[0], 0.5 * h, pi, r);
  axis_flow<1, kSmall, false>(inv[1], 0.5 * h, pi, r);
  axis_flow<2, kSmall, false>(inv[2], h, pi, r);
  axis_flow<1, kSmall, false>(inv[1], 0.5 * h, pi, r);
  axis_flow<0, kSmall, false>(inv[0], 0.5 * h, pi, r);
  const Quat o = mul(q, r);
  const double inv_norm = 1.0 / std::sqrt(o.w * o.w + o.x * o.x + o.y * o.y + o.z * o.z);
  return {o.w * inv_norm, o.x * inv_norm, o.y * inv_norm, o.z * inv_norm};
}

}  // namespace tumble::kernel
