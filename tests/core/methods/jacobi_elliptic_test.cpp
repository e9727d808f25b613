// The double-precision Jacobi sn, cn, dn (descending Landen) against
// boost::math::jacobi_elliptic, which evaluates in long double: ≤ 1e-14 absolute
// over k ∈ [0, 1) up to k = 1 - 1e-16 and |u| ≤ 1e3.
//
// Excluded: Boost's dn = cos φ₀ / cos(φ₁ - φ₀) (DLMF 22.20(ii)) is 0/0 at
// u = (2j + 1)K; its error is ~ulp(φ₁)/|cn| in long double, 4e-14 at |u| ~ 1e3,
// |cn| ~ 1e-3 (checked against 50-digit cpp_bin_float, where this code is within
// 1e-16). So dn is compared with Boost's dn only where |cn| ≥ 0.1, and everywhere
// with √(cn² + k'² sn²) formed from Boost's sn and cn (DLMF 22.6.1).
#include <gtest/gtest.h>

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "core/methods/jacobi_elliptic.hpp"

namespace tumble {
namespace {

constexpr double kTol = 1e-14;

std::vector<double> moduli() {
  std::vector<double> ks = {0,   1e-12, 1e-8, 1e-4,  1e-2, 0.1,        0.3,        0.5,
                            0.7, 0.9,   0.99, 0.999, 0.9999, 1 - 1e-6, 1 - 1e-9, 1 - 1e-12,
                            1 - 1e-15, std::nextafter(1.0, 0.0)};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uk(0, 1);
  for (int i = 0; i < 10; ++i) ks.push_back(uk(rng));
  return ks;
}

// Arguments: near 0, random over a few periods and up to ±1e3, and at and
// next to the quarter periods jK, where sn, cn, dn turn.
std::vector<double> arguments(double k, std::mt19937_64& rng) {
  std::vector<double> us = {0, 1e-300, 1e-10, -1e-5, 0.5, -1, 3};
  std::uniform_real_distribution<double> near(-30, 30), far(-1e3, 1e3);
  for (int i = 0; i < 300; ++i) us.push_back(near(rng));
  for (int i = 0; i < 300; ++i) us.push_back(far(rng));
  const double K = boost::math::ellint_1(k);
  for (int j = -5; j <= 40; ++j)
    for (double du : {0.0, 1e-9, -1e-6, 1e-3}) us.push_back(j * K + du);
  return us;
}

struct MaxErr {
  double sn = 0, cn = 0, dn = 0, dn_formed = 0;
};

TEST(JacobiElliptic, MatchesBoostOverModuliAndArguments) {
  std::mt19937_64 rng(3);
  for (double k : moduli()) {
    MaxErr e;
    const double kc = std::sqrt((1 - k) * (1 + k));
    for (double u : arguments(k, rng)) {
      double cn_b = 0, dn_b = 0;
      const double sn_b = boost::math::jacobi_elliptic(k, u, &cn_b, &dn_b);
      const JacobiSnCnDn r = jacobi_sn_cn_dn(u, k);
      e.sn = std::max(e.sn, std::abs(r.sn - sn_b));
      e.cn = std::max(e.cn, std::abs(r.cn - cn_b));
      if (std::abs(cn_b) >= 0.1) e.dn = std::max(e.dn, std::abs(r.dn - dn_b));
      const double dn_formed = std::sqrt(cn_b * cn_b + kc * kc * sn_b * sn_b);
      e.dn_formed = std::max(e.dn_formed, std::abs(r.dn - dn_formed));
    }
    EXPECT_LE(e.sn, kTol) << "k=" << k;
    EXPECT_LE(e.cn, kTol) << "k=" << k;
    EXPECT_LE(e.dn, kTol) << "k=" << k;
    EXPECT_LE(e.dn_formed, kTol) << "k=" << k;
  }
}

// With k' from the caller (as FreeRotationExact passes it), over the range
// |u| ≤ 2K the caller's own reduction by 4K leaves.
TEST(JacobiElliptic, CallerComplementaryModulus) {
  std::mt19937_64 rng(5);
  for (double k : moduli()) {
    const double kc = std::sqrt((1 - k) * (1 + k));
    const double K = boost::math::ellint_1(k);
    std::uniform_real_distribution<double> ur(-2 * K, 2 * K);
    double err = 0;
    for (int i = 0; i < 500; ++i) {
      const double u = ur(rng);
      double cn_b = 0, dn_b = 0;
      const double sn_b = boost::math::jacobi_elliptic(k, u, &cn_b, &dn_b);
      const JacobiSnCnDn r = jacobi_sn_cn_dn(u, k, kc);
      err = std::max({err, std::abs(r.sn - sn_b), std::abs(r.cn - cn_b),
                      std::abs(r.dn - std::sqrt(cn_b * cn_b + kc * kc * sn_b * sn_b))});
    }
    EXPECT_LE(err, kTol) << "k=" << k;
  }
}

TEST(JacobiElliptic, SpecialValues) {
  for (double u : {-7.0, -0.3, 0.0, 2.0, 1e3}) {
    const JacobiSnCnDn r0 = jacobi_sn_cn_dn(u, 0.0);
    EXPECT_EQ(r0.sn, std::sin(u));
    EXPECT_EQ(r0.cn, std::cos(u));
    EXPECT_EQ(r0.dn, 1.0);
    const JacobiSnCnDn r1 = jacobi_sn_cn_dn(u, 1.0);  // k = 1: tanh, sech, sech
    EXPECT_NEAR(r1.sn, std::tanh(u), 1e-16);
    EXPECT_NEAR(r1.cn, 1 / std::cosh(u), 1e-16);
    EXPECT_EQ(r1.dn, r1.cn);
  }
  for (double k : {0.3, 0.9, 1 - 1e-12}) {
    const JacobiSnCnDn r = jacobi_sn_cn_dn(0.0, k);
    EXPECT_EQ(r.sn, 0.0);
    EXPECT_EQ(r.cn, 1.0);
    EXPECT_EQ(r.dn, 1.0);
  }
}

// Near the separatrix dn(K) = k' is tiny; it must stay relatively accurate
// (it is |Π₃'| / max there), which 1 - k² sn² would lose.
TEST(JacobiElliptic, DnAtQuarterPeriodNearSeparatrix) {
  for (double k : {1 - 1e-6, 1 - 1e-9, 1 - 1e-12}) {
    const double kc = std::sqrt((1 - k) * (1 + k));
    const double K = boost::math::ellint_1(k);
    const JacobiSnCnDn r = jacobi_sn_cn_dn(K, k, kc);
    EXPECT_NEAR(r.sn, 1.0, 1e-15) << "k=" << k;
    EXPECT_NEAR(r.dn / kc, 1.0, 1e-9) << "k=" << k;
  }
}

}  // namespace
}  // namespace tumble
