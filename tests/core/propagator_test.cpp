// Propagator: samples land exactly on the requested times (a scene's frames),
// fixed-step methods split each interval into ⌈Δ/dt⌉ equal steps, and a run
// that blows up throws Diverged naming the time, step, body and method.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

#include "core/error.hpp"
#include "core/free_rotation_exact.hpp"
#include "core/propagator.hpp"
#include "core/quaternion.hpp"
#include "reference_problem.hpp"
#include "test_helpers.hpp"

namespace tumble {
namespace {

// A scene-like run: 30 fps for 2 s with dt = 1e-2 (frames are 1/30 s apart, not a
// multiple of dt). Every sample must be at exactly the frame time, each frame takes
// ⌈(1/30)/0.01⌉ = 4 steps, and the states agree with the exact solution.
TEST(Propagator, SceneLikeRunSamplesExactTimes) {
  const RigidBodyModel m = testing::reference_model();
  const BodyState s0 = testing::reference_state(m);
  const FreeRotationExact ex(m.inertia, s0.q, s0.L);
  for (Method method : {Method::rk4, Method::splitting4, Method::exact, Method::rk45}) {
    StepConfig cfg;
    cfg.method = method;
    cfg.dt = 1e-2;
    Propagator p(m, s0, cfg);
    double worst = 0;
    for (int frame = 1; frame <= 60; ++frame) {
      const double t = frame / 30.0;
      const BodyState& s = p.advance_to(t);
      EXPECT_EQ(p.time(), t) << testing::name_of(method) << " frame " << frame;
      worst = std::max(worst, rotation_angle_between(s.q, ex.orientation(t)));
    }
    if (method == Method::rk4 || method == Method::splitting4) {
      EXPECT_EQ(p.steps(), 60 * 4) << testing::name_of(method);
    }
    // rk4/splitting4 at h = 1/120 s: ~1e-5 rad over the first flip; exact: round-off.
    EXPECT_LT(worst, method == Method::exact ? 1e-11 : 1e-4) << testing::name_of(method);
    // Re-requesting the current time is a no-op.
    const BodyState again = p.advance_to(2.0);
    EXPECT_EQ(again.q.coeffs(), p.state().q.coeffs());
  }
}

TEST(Propagator, AdvanceStepsTakesExactlyNSteps) {
  const RigidBodyModel m = testing::reference_model();
  const BodyState s0 = testing::reference_state(m);
  StepConfig cfg;
  cfg.method = Method::splitting;
  cfg.dt = 1e-3;
  Propagator p(m, s0, cfg);
  p.advance_steps(250);
  EXPECT_EQ(p.steps(), 250);
  const BodyState direct = testing::run_steps(Method::splitting, m, s0, 1e-3, 250);
  EXPECT_LT(rotation_angle_between(p.state().q, direct.q), 1e-15);
}

// Runs `p` far past its divergence and returns what it threw (fails if nothing).
std::optional<Diverged> run_until_diverged(Propagator& p) {
  try {
    p.advance_to(1000.0);
  } catch (const Diverged& e) {
    return e;
  }
  return std::nullopt;
}

// Explicit Euler with a huge step on a fast spin: ω dt = 50 rad per step. The
// body (0.1, 1.9, 2.0) starts spinning about its major axis with a small tilt;
// Euler's orientation update rotates about ω by ~π per step and throws the spin
// towards the minor axis, multiplying the torque-free energy by up to I3/I1 = 20,
// which the guard reports (> 10×) — as a non-finite state would be.
TEST(Propagator, DivergingRunThrowsWithTimeStepBodyAndMethod) {
  const RigidBodyModel m = testing::body_with_moments({0.1, 1.9, 2.0}, 1.0, "spinning top");
  BodyState s0 = testing::spinning_state(m, Eigen::Quaterniond::Identity(), {3.0, 2.0, 50.0});
  StepConfig cfg;
  cfg.method = Method::euler;
  cfg.dt = 1.0;
  Propagator p(m, s0, cfg);
  const auto e = run_until_diverged(p);
  ASSERT_TRUE(e) << "expected Diverged";
  const std::string what = e->what();
  EXPECT_NE(what.find("diverged at t="), std::string::npos) << what;
  EXPECT_NE(what.find("step"), std::string::npos) << what;
  EXPECT_NE(what.find("spinning top"), std::string::npos) << what;
  EXPECT_NE(what.find("euler"), std::string::npos) << what;
  EXPECT_GT(e->step_index, 0);
  EXPECT_GE(e->time, 0.0);
  std::printf("%s\n", what.c_str());
}

// With forces the energy is not invariant; a non-finite state is what trips the
// guard: linear damping k/M = 100/s with dt = 1 s makes Euler multiply P by -99.
TEST(Propagator, NonFiniteStateThrowsDiverged) {
  RigidBodyModel m = testing::body_with_moments({1, 2, 3}, 1.0, "damped");
  m.forces.linear_damping = 100.0;
  BodyState s0 = testing::spinning_state(m, Eigen::Quaterniond::Identity(), {0.1, 1, 0.1});
  s0.P = {1, 0, 0};
  StepConfig cfg;
  cfg.method = Method::euler;
  cfg.dt = 1.0;
  Propagator p(m, s0, cfg);
  const auto e = run_until_diverged(p);
  ASSERT_TRUE(e) << "expected Diverged";
  const std::string what = e->what();
  EXPECT_NE(what.find("diverged at t="), std::string::npos) << what;
  EXPECT_NE(what.find("damped"), std::string::npos) << what;
  EXPECT_NE(what.find("euler"), std::string::npos) << what;
}

}  // namespace
}  // namespace tumble
