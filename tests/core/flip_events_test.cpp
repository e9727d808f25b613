// Flip events: the N-th sign change of Π₂, from the closed form and
// from the stepped motion of a body with torque terms.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/dynamics.hpp"
#include "core/flip_events.hpp"
#include "core/methods/free_rotation_exact.hpp"
#include "reference_problem.hpp"

namespace tumble {
namespace {

TEST(FlipEvents, SignChangesOfSineAreMultiplesOfPi) {
  const auto t = sign_change_times([](double x) { return std::sin(x); }, 0, 10, 0.1);
  ASSERT_EQ(t.size(), 3u);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(t[i], (i + 1) * std::numbers::pi, 1e-10);
}

TEST(FlipEvents, ZeroIsNoSignAndTouchingZeroIsNoChange) {
  EXPECT_TRUE(sign_change_times([](double) { return 0.0; }, 0, 5, 0.1).empty());
  // (x - 2)² touches 0 at a sample without changing sign.
  EXPECT_TRUE(sign_change_times([](double x) { return (x - 2) * (x - 2); }, 0, 5, 0.5).empty());
}

TEST(FlipEvents, ClosedFormFlipsHaveZeroPi2HalfAPeriodApart) {
  const RigidBodyModel m = testing::reference_model();
  const BodyState s0 = testing::reference_state(m);
  const FreeRotationExact ex(m.inertia, s0.q, s0.L);
  const std::vector<double> t = flip_times(m, s0, StepConfig{Method::exact}, 12.0);
  ASSERT_GE(t.size(), 3u);
  const double L = s0.L.norm();
  for (double ti : t) EXPECT_LT(std::abs(ex.momentum_body(ti)[1]) / L, 1e-9) << ti;
  // Π₂ goes through 0 twice per body period, once on each side of the polhode.
  EXPECT_NEAR(t[2] - t[0], ex.body_period(), 1e-8);
  // And it really is a reversal: Π₂ has opposite signs just before and after.
  EXPECT_LT(ex.momentum_body(t[0] - 0.05)[1] * ex.momentum_body(t[0] + 0.05)[1], 0);
}

TEST(FlipEvents, SteppedMotionWithTorqueTermsFindsTheSameFlips) {
  // A zero torque makes the body "not free" without changing its motion:
  // the stepped search must agree with the closed form.
  const RigidBodyModel free = testing::reference_model();
  ForceSet forces;
  forces.terms.push_back(ConstantTorque{});
  const RigidBodyModel torqued = make_model("torqued", compute_mass_properties(testing::reference_cloud(), "r"), forces);
  ASSERT_TRUE(torqued.forces.has_torque());
  const BodyState s0 = testing::reference_state(free);
  const std::vector<double> exact = flip_times(free, s0, StepConfig{Method::exact}, 6.0);
  const std::vector<double> stepped = flip_times(torqued, s0, StepConfig{Method::rk4, 1e-3}, 6.0);
  ASSERT_EQ(stepped.size(), exact.size());
  ASSERT_FALSE(exact.empty());
  for (std::size_t i = 0; i < exact.size(); ++i) EXPECT_NEAR(stepped[i], exact[i], 1e-6);
}

TEST(FlipEvents, WobbleNearTheLargestOrSmallestAxisIsNoFlip) {
  const RigidBodyModel m = testing::reference_model();
  for (const Eigen::Vector3d& w : {Eigen::Vector3d(10, 1, 1), Eigen::Vector3d(1, 1, 10)}) {
    InitialConditions ic;
    ic.omega = w;
    const BodyState s0 = make_state(m, ic);
    // e2 does cross ⊥ L as it wobbles...
    const FreeRotationExact ex(m.inertia, s0.q, s0.L);
    EXPECT_FALSE(sign_change_times([&](double t) { return ex.momentum_body(t)[1]; }, 0, 12, 0.01).empty());
    // ...but never turns over.
    EXPECT_TRUE(flip_times(m, s0, StepConfig{Method::exact}, 12.0).empty()) << w.transpose();
  }
}

}  // namespace
}  // namespace tumble
