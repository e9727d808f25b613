// The speed-ups of the core must not change results: the scalar quaternion rate
// and the unrolled rk4/euler give the same bits as the Eigen expression and the
// tableau form; the splitting kernel's sincos is within 1 ulp of libm and its
// sparse quaternion products equal the full ones (the splitting map against
// its plain form: reference_kernels_test.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/methods/explicit_rk.hpp"
#include "core/methods/rotation_steps.hpp"
#include "core/methods/splitting_kernel.hpp"
#include "test_helpers.hpp"

namespace tumble {
namespace {

bool same_bits(const BodyState& a, const BodyState& b) {
  return a.c == b.c && a.q.coeffs() == b.q.coeffs() && a.P == b.P && a.L == b.L;
}

struct Case {
  RigidBodyModel m;
  BodyState s;
};

// Random bodies and states; P nonzero so the sign of a zero momentum never matters.
std::vector<Case> cases(bool forced) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Case> out;
  for (int i = 0; i < 200; ++i) {
    Case c;
    c.m = testing::body_with_moments({1 + 0.3 * std::abs(u(rng)), 2 + 0.2 * u(rng), 3 + 0.5 * std::abs(u(rng))},
                                     1 + std::abs(u(rng)));
    if (forced) {
      c.m.forces.terms.push_back(UniformGravity{Eigen::Vector3d(0, 0, -9.81)});
      c.m.forces.terms.push_back(PointForce{{u(rng), u(rng), u(rng)}, {u(rng), 0, 0}, Frame::body});
      c.m.forces.terms.push_back(AngularDamping{0.1 * std::abs(u(rng))});
    }
    c.s = testing::spinning_state(c.m, Eigen::Quaterniond(u(rng), u(rng), u(rng), u(rng)),
                                  {10 * u(rng), 10 * u(rng), 10 * u(rng)});
    c.s.c = {u(rng), u(rng), u(rng)};
    c.s.P = {1 + u(rng), 2 + u(rng), -2 + u(rng)};
    out.push_back(c);
  }
  return out;
}

TEST(FastPath, QuaternionRateMatchesEigenExpression) {
  for (const Case& c : cases(false)) {
    for (double scale : {1.0, 1.0 + 1e-3, 0.97}) {  // RK stages are not unit quaternions
      const Eigen::Quaterniond q(scale * c.s.q.coeffs());
      // The body-frame form of dynamics.hpp: (-u·ω', w ω' + (2|q|² - 1) u × ω'), ω' = ½ ω_b.
      const Eigen::Vector3d wh = (0.5 * c.m.inv_inertia).cwiseProduct(q.conjugate() * c.s.L);
      const Eigen::Vector3d gu = (2 * q.coeffs().squaredNorm() - 1) * q.vec();
      Eigen::Vector4d expected;
      expected << q.w() * wh + gu.cross(wh), -q.vec().dot(wh);
      EXPECT_EQ(quaternion_rate(c.m, q, c.s.L), expected);
    }
  }
}

// ... which is the world-frame rate ½ (ω_world ⊗ q) as Eigen spells it, also off
// the unit sphere (Eigen's q v there is q v q̄ + (1 - |q|²) v), up to round-off.
TEST(FastPath, QuaternionRateIsTheWorldFrameRate) {
  for (const Case& c : cases(false)) {
    for (double scale : {1.0, 1.0 + 1e-3, 0.97, 0.5, 1.7}) {
      const Eigen::Quaterniond q(scale * c.s.q.coeffs());
      const Eigen::Vector3d w = q * c.m.inv_inertia.cwiseProduct(q.conjugate() * c.s.L);
      const Eigen::Vector4d world = 0.5 * (pure(w) * q).coeffs();
      const double size = c.m.inv_inertia.maxCoeff() * c.s.L.norm() * std::max(scale, std::pow(scale, 5));
      EXPECT_LT((quaternion_rate(c.m, q, c.s.L) - world).cwiseAbs().maxCoeff(), 1e-15 * size) << scale;
    }
  }
}

TEST(FastPath, UnrolledRk4AndEulerGiveTheTableauBits) {
  for (bool forced : {false, true})
    for (const Case& c : cases(forced))
      for (double h : {1e-3, 0.05, 0.7}) {
        EXPECT_TRUE(same_bits(rk4_step(c.m, c.s, 0.3, h), explicit_rk_step(kRk4Tableau, c.m, c.s, 0.3, h)))
            << "rk4 forced=" << forced << " h=" << h;
        EXPECT_TRUE(same_bits(euler_step(c.m, c.s, 0.3, h), explicit_rk_step(kEulerTableau, c.m, c.s, 0.3, h)))
            << "euler forced=" << forced << " h=" << h;
      }
}

// Distance in units in the last place between two doubles of the same sign.
double ulps(double a, double b) {
  if (a == b) return 0;
  return std::abs(a - b) / (std::nextafter(std::abs(b), INFINITY) - std::abs(b));
}

TEST(FastPath, SincosKernelWithinOneUlpOfLibm) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-kernel::kPiOver4, kernel::kPiOver4);
  std::vector<double> xs = {0.0, -0.0, 1e-300, 1e-9, 0.3, 0.5, 0.78, kernel::kPiOver4, -kernel::kPiOver4};
  for (int i = 0; i < 200000; ++i) xs.push_back(u(rng));
  for (int e = -30; e < 0; ++e) xs.push_back(std::ldexp(0.7, e));  // small arguments
  double worst_s = 0, worst_c = 0;
  for (double x : xs) {
    double s, c;
    kernel::sincos_small(x, s, c);
    worst_s = std::max(worst_s, ulps(s, std::sin(x)));
    worst_c = std::max(worst_c, ulps(c, std::cos(x)));
    kernel::sincos_msun(x, s, c);  // the general path's evaluation order
    worst_s = std::max(worst_s, ulps(s, std::sin(x)));
    worst_c = std::max(worst_c, ulps(c, std::cos(x)));
  }
  // The tiny-angle series on its own range |x| ≤ kTinyAngle = 1/32.
  std::uniform_real_distribution<double> t(-kernel::kTinyAngle, kernel::kTinyAngle);
  std::vector<double> tiny = {0.0, -0.0, 1e-300, 1e-9, kernel::kTinyAngle, -kernel::kTinyAngle};
  for (int i = 0; i < 200000; ++i) tiny.push_back(t(rng));
  for (int e = -40; e < -6; ++e) tiny.push_back(std::ldexp(0.9, e));
  for (double x : tiny) {
    double s, c;
    kernel::sincos_tiny(x, s, c);
    worst_s = std::max(worst_s, ulps(s, std::sin(x)));
    worst_c = std::max(worst_c, ulps(c, std::cos(x)));
  }
  EXPECT_LE(worst_s, 1.0);
  EXPECT_LE(worst_c, 1.0);
  RecordProperty("worst_ulps_sin", std::to_string(worst_s));
  RecordProperty("worst_ulps_cos", std::to_string(worst_c));
}

TEST(FastPath, SparseAxisProductEqualsFullProduct) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 1000; ++i) {
    const kernel::Quat a{u(rng), u(rng), u(rng), u(rng)};
    const double ch = u(rng), sh = u(rng);
    const kernel::Quat r[3] = {kernel::mul_axis<0>(a, ch, sh), kernel::mul_axis<1>(a, ch, sh),
                               kernel::mul_axis<2>(a, ch, sh)};
    const kernel::Quat f[3] = {kernel::mul(a, {ch, sh, 0, 0}), kernel::mul(a, {ch, 0, sh, 0}),
                               kernel::mul(a, {ch, 0, 0, sh})};
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(r[k].w, f[k].w);
      EXPECT_EQ(r[k].x, f[k].x);
      EXPECT_EQ(r[k].y, f[k].y);
      EXPECT_EQ(r[k].z, f[k].z);
    }
  }
}

}  // namespace
}  // namespace tumble
