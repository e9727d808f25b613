// The arithmetic of one torque-free `splitting` rotation on plain doubles, shared
// by core's splitting_step and the structure-of-arrays bench kernel so both give
// the same bits. Header-only and call-free on the fast path so loops over many
// bodies vectorise.
//
// Contract with the plain form (free_rotation_splitting_reference in
// rotation_steps.hpp, libm sin/cos and Eigen products): the same map, not the
// same bits. Its sin/cos are polynomials within 1 ulp of libm and its products
// drop exact zeros and reassociate, so for a unit q the output quaternion's
// components differ from the reference's by at most 2e-15 while every sub-flow
// angle |θ| ≤ kSmallAngle (h|ω| ≲ 1/8), 3e-14 at h|ω| ~ 10 and 1e-10 at
// h|ω| ~ 50 (a 1-ulp difference grows by ~(1 + |θ|) per sub-flow).
// tests/core/reference_kernels_test.cpp holds them to it.
#pragma once

#include <cmath>

namespace tumble::kernel {

inline constexpr double kPiOver4 = 0.78539816339744830962;
/// Largest sub-flow angle |θ| of splitting_rotation_small (h|ω| ≲ 1/8, any
/// sensible step): its errors grow by ~(1 + |θ|) per sub-flow, so they stay at
/// round-off against the reference arithmetic (within 2e-15).
inline constexpr double kSmallAngle = 0.125;

/// FreeBSD msun k_sin.c / k_cos.c minimax coefficients for |x| ≤ π/4.
namespace msun {
inline constexpr double S1 = -1.66666666666666324348e-01, S2 = 8.33333333332248946124e-03,
                        S3 = -1.98412698298579493134e-04, S4 = 2.75573137070700676789e-06,
                        S5 = -2.50507602534068634195e-08, S6 = 1.58969099521155010221e-10;
inline constexpr double C1 = 4.16666666666666019037e-02, C2 = -1.38888888888741095749e-03,
                        C3 = 2.48015872894767294178e-05, C4 = -2.75573143513906633035e-07,
                        C5 = 2.08757232129817482790e-09, C6 = -1.13596475577881948265e-11;
}  // namespace msun

/// sin and cos for |x| ≤ π/4 (FreeBSD msun k_sin.c / k_cos.c coefficients,
/// error < 1 ulp): no range reduction, no branches, no libm call. The
/// polynomials in z = x² go by Estrin's scheme (x³z²ⁿ powers formed alongside
/// the coefficient pairs): depth 7 (sin) and 8 (cos) instead of msun's 10.
[[gnu::always_inline]] inline void sincos_small(double x, double& s, double& c) {
  using namespace msun;
  const double z = x * x, w = z * z, w2 = w * w, xz = x * z;
  // sin = x + x³(S1 + S2 z) + x³z²(S3 + S4 z) + x³z⁴(S5 + S6 z).
  s = x + ((xz * (S1 + S2 * z) + (xz * w) * (S3 + S4 * z)) + (xz * w2) * (S5 + S6 * z));
  // cos = 1 - z/2 + z²(C1 + C2 z) + z⁴(C3 + C4 z) + z⁶(C5 + C6 z).
  const double tail = (w * (C1 + C2 * z) + w2 * (C3 + C4 * z)) + (w2 * w) * (C5 + C6 * z);
  const double hz = 0.5 * z, a = 1.0 - hz;
  c = a + (((1.0 - a) - hz) + tail);  // recovers the rounding of 1 - z/2 (k_cos.c)
}

/// Largest |x| for sincos_tiny, and the largest sub-flow angle of its path
/// (h|ω| ≲ 1/32 whatever the sub-flow order: dt ≤ 3 ms at 10 rad/s). 1/32, not
/// 1/64: with the smallest moment's axis innermost (a full step) the bound
/// h|Π|/I₁ of the reference problem at dt = 1 ms is 0.02.
inline constexpr double kTinyAngle = 1.0 / 32;

/// sin and cos for |x| ≤ 1/32 by their Taylor series, cut where the next term is
/// below 3e-17 (x⁹/9! relative to x, x⁸/8!: at most 0.2 ulp; measured within
/// 1 ulp of libm, tests/core/fast_path_test.cpp), in depth 6 instead of 7–8: for the
/// latency of one body's chain of sub-flows. cos = 1 + (z²/24 - z/2 - z³/720)
/// rounds once at the end, so it is as accurate as msun's 1 - z/2 correction.
[[gnu::always_inline]] inline void sincos_tiny(double x, double& s, double& c) {
  constexpr double S1 = -1.0 / 6, S2 = 1.0 / 120, S3 = -1.0 / 5040;
  constexpr double C1 = 1.0 / 24, C2 = -1.0 / 720;
  const double z = x * x, w = z * z, xz = x * z;
  s = x + xz * ((S1 + z * S2) + w * S3);
  c = 1.0 + ((w * C1 - 0.5 * z) + (w * z) * C2);
}

/// sin and cos for |x| ≤ π/4 (FreeBSD msun k_sin.c / k_cos.c kernels, error
/// < 1 ulp) in msun's own evaluation order: the general path keeps its bits.
[[gnu::always_inline]] inline void sincos_msun(double x, double& s, double& c) {
  using namespace msun;
  const double z = x * x, w = z * z;
  const double rs = S2 + z * (S3 + z * S4) + z * w * (S5 + z * S6);
  s = x + z * x * (S1 + z * rs);
  const double rc = z * (C1 + z * (C2 + z * C3)) + w * w * (C4 + z * (C5 + z * C6));
  const double hz = 0.5 * z, a = 1.0 - hz;
  c = a + (((1.0 - a) - hz) + z * rc);  // recovers the rounding of 1 - z/2
}

/// sin and cos for any x: the kernel inside ±π/4, libm outside.
inline void sincos_any(double x, double& s, double& c) {
  if (std::abs(x) <= kPiOver4) return sincos_msun(x, s, c);
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
template <int I, bool kFirst>
[[gnu::always_inline]] inline void axis_flow(double inv_i, double tau, double pi[3], Quat& r) {
  const double half = 0.5 * tau * pi[I] * inv_i;
  double sh, ch;
  sincos_any(half, sh, ch);
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

/// Sub-flow orders: principal axes (A, B, C) give the symmetric sequence
/// A(h/2) B(h/2) C(h) B(h/2) A(h/2). Index = SplitOrder of rotation_steps.hpp.
inline constexpr int kSplitAxes[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};

/// The splitting map for any angle, sub-flow by sub-flow (the arithmetic of
/// the plain form, free_rotation_splitting_reference). Used beyond
/// kSmallAngle: each sub-flow amplifies a 1-ulp difference by ~(1 + |θ|), so at
/// h|ω| ~ 10 only the reference's own operations stay within 3e-14 of it.
template <int A, int B, int C>
[[gnu::always_inline]] inline Quat splitting_rotation_general(const Quat& q, const double l[3], const double inv[3], double h) {
  // Π = q̄ L (Eigen's formula: L + 2w (v × L) + v × 2(v × L) with v = -q.vec).
  const double vx = -q.x, vy = -q.y, vz = -q.z;
  const double ux = 2 * (vy * l[2] - vz * l[1]), uy = 2 * (vz * l[0] - vx * l[2]), uz = 2 * (vx * l[1] - vy * l[0]);
  double pi[3] = {l[0] + q.w * ux + (vy * uz - vz * uy), l[1] + q.w * uy + (vz * ux - vx * uz),
                  l[2] + q.w * uz + (vx * uy - vy * ux)};
  Quat r;
  axis_flow<A, true>(inv[A], 0.5 * h, pi, r);
  axis_flow<B, false>(inv[B], 0.5 * h, pi, r);
  axis_flow<C, false>(inv[C], h, pi, r);
  axis_flow<B, false>(inv[B], 0.5 * h, pi, r);
  axis_flow<A, false>(inv[A], 0.5 * h, pi, r);
  const Quat o = mul(q, r);
  const double inv_norm = 1.0 / std::sqrt(o.w * o.w + o.x * o.x + o.y * o.y + o.z * o.z);
  return {o.w * inv_norm, o.x * inv_norm, o.y * inv_norm, o.z * inv_norm};
}

/// k·Πₙ after a sub-flow about axis I turned (Πⱼ, Πₖ) by (c, s), formed from the
/// pre-scaled old components (c·(k Πⱼ) + s·(k Πₖ)) so the products are off the chain.
template <int I, int N>
[[gnu::always_inline]] inline double turned_scaled(double c, double s, const double p[3], double k) {
  constexpr int J = (I + 1) % 3, K = (I + 2) % 3;
  if constexpr (N == J) return c * (k * p[J]) + s * (k * p[K]);
  else if constexpr (N == K) return -s * (k * p[J]) + c * (k * p[K]);
  else return k * p[I];
}

/// Π after a sub-flow about axis I: (Πⱼ, Πₖ) ← (c Πⱼ + s Πₖ, -s Πⱼ + c Πₖ).
template <int I>
[[gnu::always_inline]] inline void turn(double c, double s, double p[3]) {
  constexpr int J = (I + 1) % 3, K = (I + 2) % 3;
  const double pj = p[J], pk = p[K];
  p[J] = c * pj + s * pk;
  p[K] = -s * pj + c * pk;
}

/// The same map when every sub-flow angle |θ| = |τ Πᵢ/Iᵢ| ≤ kSmallAngle, written
/// for latency (one body's steps form one dependency chain, through the
/// angles): Π takes sincos θ directly (no double angle from θ/2; the r factors
/// are off the chain), the next angle k Πₙ' is formed from pre-scaled
/// components (turned_scaled), the updates of Π that are not read again are
/// dead and dropped by the compiler, and as |r| = 1, normalise(q ⊗ r) =
/// (q ⊗ r)/|q| with 1/|q| and q ⊗ r₁…r₄ formed while the angles run. Each is
/// an identity, so results move only by round-off (the output norm is 1 within
/// a few ulps, and the next step divides by it again, so it does not drift).
template <int A, int B, int C, bool kTiny = false>
[[gnu::always_inline]] inline Quat splitting_rotation_small(const Quat& q, const double l[3], const double inv[3], double h) {
  const auto sincos_small = [](double x, double& s, double& c) {
    if constexpr (kTiny) kernel::sincos_tiny(x, s, c);
    else kernel::sincos_small(x, s, c);
  };
  // Sub-flow angles are θ = kᵢ Πᵢ: per-step constants, off the chain.
  const double kA = 0.5 * h * inv[A], kB = 0.5 * h * inv[B], kC = h * inv[C], kAh = 0.5 * kA;
  // Π = q̄ L (Eigen's formula: L + w·2(v×L) + v×2(v×L), v = -q.vec; the exact
  // doublings go onto w and v, which are ready first).
  const double vx = -q.x, vy = -q.y, vz = -q.z, w2 = q.w + q.w, vx2 = vx + vx, vy2 = vy + vy, vz2 = vz + vz;
  const double ux = vy * l[2] - vz * l[1], uy = vz * l[0] - vx * l[2], uz = vx * l[1] - vy * l[0];
  double p[3] = {l[0] + w2 * ux + (vy2 * uz - vz2 * uy), l[1] + w2 * uy + (vz2 * ux - vx2 * uz),
                 l[2] + w2 * uz + (vx2 * uy - vy2 * ux)};
  const double inv_norm = 1.0 / std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  double c, s, ch, sh;
  // 1 (axis A, h/2).
  const double tA = kA * p[A];
  sincos_small(tA, s, c);
  sincos_small(0.5 * tA, sh, ch);
  Quat r{ch, 0, 0, 0};
  (A == 0 ? r.x : A == 1 ? r.y : r.z) = sh;
  // 2 (axis B, h/2).
  const double tB = turned_scaled<A, B>(c, s, p, kB);
  turn<A>(c, s, p);
  sincos_small(tB, s, c);
  sincos_small(0.5 * tB, sh, ch);
  r = mul_axis<B>(r, ch, sh);
  // 3 (axis C, h).
  const double tC = turned_scaled<B, C>(c, s, p, kC);
  turn<B>(c, s, p);
  sincos_small(tC, s, c);
  sincos_small(0.5 * tC, sh, ch);
  r = mul_axis<C>(r, ch, sh);
  // 4 (axis B, h/2).
  const double tD = turned_scaled<C, B>(c, s, p, kB);
  turn<C>(c, s, p);
  sincos_small(tD, s, c);
  sincos_small(0.5 * tD, sh, ch);
  r = mul_axis<B>(r, ch, sh);
  // 5 (axis A, h/2): only its half angle; q ⊗ r₁…r₄ / |q| is ready by now.
  const double hE = turned_scaled<B, A>(c, s, p, kAh);
  const Quat qr = mul(q, r), qn{qr.w * inv_norm, qr.x * inv_norm, qr.y * inv_norm, qr.z * inv_norm};
  sincos_small(hE, sh, ch);
  return mul_axis<A>(qn, ch, sh);
}

/// NO_SQUISH / DLM symmetric splitting A(h/2) B(h/2) C(h) B(h/2) A(h/2) of the
/// free rotation: q ← normalise(q ⊗ r) with world L (l) fixed. `kSmall` = the
/// caller guarantees every sub-flow angle |θ| = |τ Πᵢ/Iᵢ| ≤ kSmallAngle;
/// otherwise the bound sub_flow_angle_factor·|Π| picks the path (every sub-flow
/// keeps |Π|; a predicted branch, so its test is off the chain).
/// f with every sub-flow angle |θ| ≤ f |Π| (|Π| = |L| for a unit q).
template <int A = 0, int B = 1, int C = 2>
[[gnu::always_inline]] inline double sub_flow_angle_factor(const double inv[3], double h) {
  const double a0 = 0.5 * inv[A], a1 = 0.5 * inv[B], a2 = inv[C];
  return std::abs(h) * (a0 > a1 ? (a0 > a2 ? a0 : a2) : (a1 > a2 ? a1 : a2));
}

template <bool kSmall, int A = 0, int B = 1, int C = 2>
[[gnu::always_inline]] inline Quat splitting_rotation(const Quat& q, const double l[3], const double inv[3], double h) {
  if constexpr (kSmall) {
    return splitting_rotation_small<A, B, C>(q, l, inv, h);
  } else {
    // Eigen's q̄ L is q̄ L q + (1 - |q|²) L, so |Π| ≤ (|q|² + |1 - |q|²|) |L|.
    const double nq = q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z, g = nq + std::abs(1 - nq);
    // Sub-flows A and B run for h/2, sub-flow C for h.
    const double a = sub_flow_angle_factor<A, B, C>(inv, h);
    const double b = a * a * g * g * (l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
    if (b <= (0.99 * kTinyAngle) * (0.99 * kTinyAngle)) [[likely]]
      return splitting_rotation_small<A, B, C, true>(q, l, inv, h);
    if (b <= (0.99 * kSmallAngle) * (0.99 * kSmallAngle)) return splitting_rotation_small<A, B, C>(q, l, inv, h);
    return splitting_rotation_general<A, B, C>(q, l, inv, h);
  }
}

/// Index into kSplitAxes of the order (outer a, middle b): rows go by a, then
/// by whether b is the larger of the two others.
constexpr int split_index(int a, int b) { return 2 * a + (b > 3 - a - b ? 1 : 0); }
static_assert(split_index(0, 1) == 0 && split_index(0, 2) == 1 && split_index(1, 0) == 2 && split_index(1, 2) == 3 &&
              split_index(2, 0) == 4 && split_index(2, 1) == 5);

/// Axes of the smallest (s), intermediate (m) and largest (l) moment from the
/// inverse moments, any axis order; false for a spherical body.
inline bool axes_by_moment(const double inv[3], int& s, int& m, int& l) {
  s = 0, l = 0;
  for (int i = 1; i < 3; ++i) {
    if (inv[i] > inv[s]) s = i;
    if (inv[i] < inv[l]) l = i;
  }
  m = 3 - s - l;
  return s != l;
}

/// The sub-flow order of `splitting` for a body (index into kSplitAxes) from
/// its inverse principal moments. Measured, not derived: the orientation error
/// at 10 s (dt = 1 ms, against the closed form) of all six symmetric orders
/// (scripts/splitting_order_study.sh). The order with the axis of the smallest
/// moment in the middle is always worst (up to 10×); the largest moment
/// outermost and the intermediate one in the middle (3,2,1,2,3 for
/// I1 ≤ I2 ≤ I3) is best or near it for compact bodies, the intermediate
/// outermost with the largest in the middle (2,3,1,3,2) for elongated ones
/// (I1 ≤ I3/4) that are not near-oblate (I3 - I2 > I2 - I1). On the first
/// study (18 bodies × 5 spins) the rule is 10^0.09 from the best order per case
/// (fixed 1,2,3,2,1: 10^0.27).
///
/// The orbit region does not matter. Fassò (J. Comput. Phys. 189, 2003) finds
/// the dominant term of the modified Hamiltonian, hence the energy error,
/// depends on the moments and on whether Π circulates about the smallest
/// (|L|² < 2E I2) or the largest moment's axis. On the wider study (18 bodies ×
/// 62 starts, 1116 cases in both regions, down to 1e-6 from the separatrix) the
/// best order per body and region is 10^0.118 from the best per case, the best
/// per body alone 10^0.131: reading the region gains at most 3% of error
/// (splitting4: 10^0.105 against 10^0.112). What matters is where Π starts:
/// this rule is the best for starts at the intermediate axis (the reference
/// problem, the Dzhanibekov demos) and 10^0.3–0.8 from the best for starts
/// beyond 8° from it, so a run fixes its order at its start
/// (split_order_for_start). Choosing per step from the current Π instead errs
/// 7.7e-5 rad on the reference problem (the start's choice: 1.4e-5).
inline int split_order(const double inv[3]) {
  int s, m, l;
  if (!axes_by_moment(inv, s, m, l)) return 5;  // spherical: every order is the same map
  // I_s ≤ I_l/4 and I_l - I_m > I_m - I_s, multiplied through by I_s I_m I_l > 0.
  const bool elongated = inv[l] <= 0.25 * inv[s] && inv[s] * inv[m] - inv[s] * inv[l] > inv[s] * inv[l] - inv[m] * inv[l];
  return elongated ? split_index(m, l) : split_index(l, m);
}

/// The base order of `splitting4` (Yoshida's triple jump cancels the base
/// map's h³ error, so other constants lead): smallest moment outermost, the
/// largest in the middle (1,3,2,3,1), best on 14 of the first study's 18 bodies
/// and on average 10^0.09 from the best order per case (fixed 1,2,3,2,1:
/// 10^0.47; `scripts/splitting_order_study.sh 4`). On the 1116 cases of the
/// wider study it is 10^0.119 from the best per case (fixed 1,2,3,2,1:
/// 10^0.48); the best single order per body would be 10^0.112, per body and
/// region or per body and start at the saddle 10^0.105: none gains measurably.
inline int split_order4(const double inv[3]) {
  int s, m, l;
  if (!axes_by_moment(inv, s, m, l)) return 5;
  return split_index(s, l);
}

/// The order for starts away from the intermediate axis: the smallest moment
/// outermost, the intermediate one in the middle (1,2,3,2,1), or the largest in
/// the middle for the bodies split_order calls elongated (1,3,2,3,1).
inline int split_order_off_saddle(const double inv[3]) {
  int s, m, l;
  if (!axes_by_moment(inv, s, m, l)) return 5;
  return split_order(inv) == split_index(m, l) ? split_index(s, l) : split_index(s, m);
}

/// The sub-flow order of a `splitting` run, chosen once from the body's
/// moments and its initial Π (body frame, any unit): split_order when Π starts
/// within 1° of the intermediate axis (the saddle: the Dzhanibekov starts and
/// the reference problem), else the smallest moment outermost with the
/// intermediate one in the middle, 1,2,3,2,1 (elongated bodies: the largest in
/// the middle, 1,3,2,3,1). Measured (scripts/splitting_order_study.sh, 18
/// bodies × 62 starts): for starts 0.15°–8° from the intermediate axis the two
/// rules are within 10^0.05 of each other, below 0.15° the moments' rule is
/// 10^0.15 better, beyond 8° the other 10^0.2–0.5 better. Over all 1116 cases
/// this choice is 10^0.146 from the best order per case, split_order alone
/// 10^0.316; a threshold anywhere from 0.15° to 5° gives the same mean within
/// 10^0.003 (from the study's csv). A body with two equal moments has no
/// saddle and keeps split_order.
inline int split_order_for_start(const double inv[3], const double pi0[3]) {
  int s, m, l;
  if (!axes_by_moment(inv, s, m, l)) return 5;
  if (inv[s] == inv[m] || inv[m] == inv[l]) return split_order(inv);
  constexpr double kCos2Saddle = 0.99969541350954794;  // cos²(1°)
  const double n2 = pi0[0] * pi0[0] + pi0[1] * pi0[1] + pi0[2] * pi0[2];
  return pi0[m] * pi0[m] >= kCos2Saddle * n2 ? split_order(inv) : split_order_off_saddle(inv);
}

/// splitting_rotation<false> with the order picked at run time (index into kSplitAxes).
[[gnu::always_inline]] inline Quat splitting_rotation_ordered(int order, const Quat& q, const double l[3], const double inv[3], double h) {
  switch (order) {
    case 1: return splitting_rotation<false, 0, 2, 1>(q, l, inv, h);
    case 2: return splitting_rotation<false, 1, 0, 2>(q, l, inv, h);
    case 3: return splitting_rotation<false, 1, 2, 0>(q, l, inv, h);
    case 4: return splitting_rotation<false, 2, 0, 1>(q, l, inv, h);
    case 5: return splitting_rotation<false, 2, 1, 0>(q, l, inv, h);
    default: return splitting_rotation<false, 0, 1, 2>(q, l, inv, h);
  }
}

}  // namespace tumble::kernel
