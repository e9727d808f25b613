// Tuned kernels against the plain Eigen forms they stand for:
// the contracts written in body_frame_tuned.hpp and splitting_kernel.hpp.
#include <gtest/gtest.h>

#include <random>

#include "core/body_frame.hpp"
#include "core/body_frame_tuned.hpp"
#include "core/methods/rotation_steps.hpp"
#include "test_helpers.hpp"

namespace tumble {
namespace {

TEST(ReferenceKernels, TunedRk4GivesTheReferenceBits) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 300; ++i) {
    const RigidBodyModel m = testing::body_with_moments(
        {1 + 0.3 * std::abs(u(rng)), 2 + 0.2 * u(rng), 3 + 0.5 * std::abs(u(rng))}, 1 + std::abs(u(rng)));
    BodyState s = testing::spinning_state(m, Eigen::Quaterniond(u(rng), u(rng), u(rng), u(rng)),
                                          {10 * u(rng), 10 * u(rng), 10 * u(rng)});
    s.c = {u(rng), u(rng), u(rng)};
    s.P = {1 + u(rng), 2 + u(rng), -2 + u(rng)};  // nonzero: the sign of a zero P is outside the contract
    for (double h : {1e-3, 1e-2, 0.3}) {
      const BodyState a = tuned::rk4_body_free(m, s, h), b = rk4_body_reference(m, s, 0.7, h);
      EXPECT_EQ(a.c, b.c);
      EXPECT_EQ(a.q.coeffs(), b.q.coeffs()) << i << " h=" << h;
      EXPECT_EQ(a.P, b.P);
      EXPECT_EQ(a.L, b.L);
      const BodyCoords x = to_body_coords(s);
      const BodyCoords c = tuned::rk4_coords_free(m, x, h), d = rk4_coords_reference(m, x, 0.7, h);
      EXPECT_EQ(c.c, d.c);
      EXPECT_EQ(c.q.coeffs(), d.q.coeffs()) << i << " h=" << h;
      EXPECT_EQ(c.P, d.P);
      EXPECT_EQ(c.pi, d.pi);
      EXPECT_EQ(c.lost_pi, d.lost_pi);
    }
  }
}

// The splitting map (splitting_kernel.hpp) against its plain form: within the
// tolerances of the kernel's contract, not bit for bit (its sin/cos are
// polynomials within 1 ulp of libm). h|ω| reaches ~17·h here: at 0.7 and 3 the
// half angles pass π/4 and take libm; each sub-flow's angle depends on Π from
// the previous one, so a 1-ulp difference grows by ~(1 + |θ|) per sub-flow.
TEST(ReferenceKernels, TunedSplittingWithinContractOfReference) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 200; ++i) {
    const RigidBodyModel m = testing::body_with_moments(
        {1 + 0.3 * std::abs(u(rng)), 2 + 0.2 * u(rng), 3 + 0.5 * std::abs(u(rng))}, 1 + std::abs(u(rng)));
    const BodyState s = testing::spinning_state(m, Eigen::Quaterniond(u(rng), u(rng), u(rng), u(rng)),
                                                {10 * u(rng), 10 * u(rng), 10 * u(rng)});
    for (auto [h, tol] : {std::pair{1e-3, 2e-15}, {0.05, 2e-15}, {0.7, 3e-14}, {3.0, 1e-10}}) {
      Eigen::Quaterniond q = s.q, ref = s.q;
      const int order = i % 6;  // every sub-flow order
      free_rotation_splitting(m, s.L, q, h, order);
      free_rotation_splitting_reference(m, s.L, ref, h, order);
      EXPECT_LT((q.coeffs() - ref.coeffs()).cwiseAbs().maxCoeff(), tol) << i << " h=" << h;
    }
  }
}

}  // namespace
}  // namespace tumble
