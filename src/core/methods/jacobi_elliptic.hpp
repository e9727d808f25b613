// Jacobi elliptic functions sn, cn, dn in double precision (descending Landen
// transformation), for the closed-form rotation in free_rotation_exact.cpp.
#pragma once

namespace tumble {

struct JacobiSnCnDn {
  double sn = 0, cn = 1, dn = 1;
};

/// sn, cn, dn(u | k) for modulus 0 ≤ k ≤ 1, given the complementary modulus
/// kc = k' = √(1 - k²) as well: near k = 1 the caller can often form k' without
/// the cancellation in 1 - k², and k' (not k) is what sets K and the period.
/// Absolute error ≲ 6e-15 (largest as k → 1, ~1e-15 for k ≤ 0.999) for |u| up to
/// 1e3 and beyond (tests/core/methods/jacobi_elliptic_test.cpp).
JacobiSnCnDn jacobi_sn_cn_dn(double u, double k, double kc);

/// As above with k' = √((1 - k)(1 + k)), which is exact to rounding for any k.
JacobiSnCnDn jacobi_sn_cn_dn(double u, double k);

}  // namespace tumble
