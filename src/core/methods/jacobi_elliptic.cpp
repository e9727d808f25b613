#include "core/methods/jacobi_elliptic.hpp"

#include <cmath>

namespace tumble {

namespace {

// Below this modulus sn(v | k) = sin v + O(k² v): k² < 1e-17 is under rounding
// for the |v| ≤ 4 the main path sees (A&S 16.13.1).
constexpr double kSmallModulus = 3e-9;
// Each step takes about the square root of k', so even k' = 1e-308 gets
// k_N < 3e-9 within ~14 steps.
constexpr int kMaxSteps = 24;

// Double-double arithmetic (value = hi + lo) for the AGM on the large-|u| path.
struct DD {
  double hi, lo;
};
DD fast_two_sum(double a, double b) {  // |a| ≥ |b|
  const double s = a + b;
  return {s, b - (s - a)};
}
DD two_sum(double a, double b) {
  const double s = a + b, bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}
DD dd_add(DD a, DD b) {
  const DD s = two_sum(a.hi, b.hi);
  return fast_two_sum(s.hi, s.lo + a.lo + b.lo);
}
DD dd_mul(DD a, DD b) {
  const double p = a.hi * b.hi;
  return fast_two_sum(p, std::fma(a.hi, b.hi, -p) + a.hi * b.lo + a.lo * b.hi);
}
DD dd_sqrt(DD a) {  // one Newton correction of the double root
  const double s = std::sqrt(a.hi);
  return fast_two_sum(s, (std::fma(-s, s, a.hi) + a.lo) / (2 * s));
}

// M(1, k') = π / (2K) to ~1e-30 relative (AGM, DLMF 19.8.1/19.8.5): once
// |a - b| ≤ 1e-16 a, one more step leaves an error ~(a - b)²/a.
DD agm_dd(DD kc) {
  DD a{1, 0}, b = kc;
  for (int i = 0; i < 64; ++i) {
    const bool last = std::abs(a.hi - b.hi) <= 1e-16 * a.hi;
    const DD s = dd_add(a, b);
    b = dd_sqrt(dd_mul(a, b));
    a = {0.5 * s.hi, 0.5 * s.lo};
    if (last) break;
  }
  return a;
}

// Descending Landen transformation (DLMF 22.7.1–22.7.3; A&S 16.12): with
// k₁ = (1 - k')/(1 + k'), v = u/(1 + k₁) and sn, cn, dn on the right at (v | k₁),
//   sn(u|k) = (1 + k₁) sn / (1 + k₁ sn²),  cn(u|k) = cn dn / (1 + k₁ sn²),
//   dn(u|k) = (1 - k₁ sn²)/(1 + k₁ sn²).
// Repeated, it is the AGM of DLMF 22.20(ii) / A&S 16.4: a₀ = 1, b₀ = k', c₀ = k,
// a_n = (a + b)/2, b_n = √(ab), c_n = c²/(4a_n), and step n has k_n = c_n/a_n,
// 1 + k_n = a_{n-1}/a_n, 1 - k_n = b_{n-1}/a_n. So, with D = a_n + c_n sn²,
//   sn ← a_{n-1} sn / D,  cn ← a_n cn dn / D,  dn ← (b_{n-1} + c_n cn²) / D:
// products and one quotient per step, no cancellation (1 - k_n is b_{n-1}/a_n,
// never formed), one sin/cos pair at the bottom, where k_N < 3e-9 makes
// sn = sin, cn = cos exact to rounding and the argument is u a_N = u π/(2K).
JacobiSnCnDn sn_cn_dn(double u, double k, DD kc) {
  k = std::abs(k);
  if (k == 0) return {std::sin(u), std::cos(u), 1.0};
  if (kc.hi <= 0) {  // k = 1: the separatrix, no period
    const double sech = 1 / std::cosh(u);
    return {std::tanh(u), sech, sech};
  }
  double a[kMaxSteps + 1], b[kMaxSteps + 1], c[kMaxSteps + 1];
  a[0] = 1;
  b[0] = kc.hi;
  c[0] = k;
  int n = 0;
  while (c[n] > kSmallModulus * a[n] && n < kMaxSteps) {
    a[n + 1] = 0.5 * (a[n] + b[n]);
    b[n + 1] = std::sqrt(a[n] * b[n]);
    // c = (a - b)/2 while a, b are apart: c²/(4a) would double c's relative
    // error each step, and k_n ≈ 1 (k near 1) weighs it fully.
    c[n + 1] = b[n] <= 0.5 * a[n] ? 0.5 * (a[n] - b[n]) : c[n] * c[n] / (4 * a[n + 1]);
    ++n;
  }
  // v = u a_N. Its error is ~|v| ulp: fine while |v| ≤ 4 (|u| ≲ 2.5 K). Beyond,
  // a_N = M(1, k') in double-double keeps v, and so sin/cos (which reduce their
  // argument exactly), accurate; this stands in for reducing u by 4K.
  double sn, cn;
  const double v = u * a[n];
  if (std::abs(v) <= 4) {
    sn = std::sin(v);
    cn = std::cos(v);
  } else {
    const DD m = agm_dd(kc);
    const double p = u * m.hi, e = std::fma(u, m.hi, -p) + u * m.lo;  // v = p + e
    const double sp = std::sin(p), cp = std::cos(p);
    sn = sp + e * cp;
    cn = cp - e * sp;
  }
  const double kN = c[n] / a[n];
  double dn = 1 - 0.5 * kN * kN * sn * sn;  // √(1 - k_N² sn²), k_N² < 1e-17
  for (; n > 0; --n) {
    const double inv = 1 / (a[n] + c[n] * sn * sn);
    const double sn_up = a[n - 1] * sn * inv;
    const double cn_up = a[n] * cn * dn * inv;
    dn = (b[n - 1] + c[n] * cn * cn) * inv;
    sn = sn_up;
    cn = cn_up;
  }
  // sn stays within ~1 ulp, but while k_n ≈ 1 (k near 1) dn ≈ cn and cn ← cn dn
  // doubles cn's relative error each step (~30 ulp at k = 1 - 1e-15). So where
  // |cn| ≥ 1/4 take cn = √((1 - sn)(1 + sn)) (error ≤ 4 that of sn), and always
  // dn = √(cn² + k'² sn²) (DLMF 22.6.1; error ≤ that of cn).
  if (sn * sn <= 0.9375) cn = std::copysign(std::sqrt((1 - sn) * (1 + sn)), cn);
  dn = std::sqrt(cn * cn + kc.hi * kc.hi * sn * sn);
  return {sn, cn, dn};
}

}  // namespace

JacobiSnCnDn jacobi_sn_cn_dn(double u, double k, double kc) { return sn_cn_dn(u, k, {kc, 0}); }

// k'² = (1 - k)(1 + k) in double-double, so the large-|u| path sees k' to ~1e-32:
// there sn depends on k' through the period, ∝ u.
JacobiSnCnDn jacobi_sn_cn_dn(double u, double k) {
  const DD kc2 = dd_mul(two_sum(1, -k), two_sum(1, k));
  const DD kc = kc2.hi > 0 ? dd_sqrt(kc2) : DD{0, 0};
  return sn_cn_dn(u, k, kc);
}

}  // namespace tumble
