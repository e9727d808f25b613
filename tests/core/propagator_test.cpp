// Propagator: samples land exactly on the requested times (a scene's frames),
// fixed-step methods step on the grid t_n = n·dt whatever the sample times,
// and a run that blows up, forced or not, throws Diverged
// naming the time, step, body and method.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

#include "core/dynamics.hpp"
#include "core/error.hpp"
#include "core/methods/free_rotation_exact.hpp"
#include "core/propagator.hpp"
#include "core/quaternion.hpp"
#include "reference_problem.hpp"
#include "test_helpers.hpp"

namespace tumble {
namespace {

// A scene-like run: 30 fps for 2 s with dt = 1e-2 (frames are 1/30 s apart, not a
// multiple of dt). Every sample must be at exactly the frame time, the grid takes
// 2 / 0.01 = 200 steps, and the states agree with the exact solution.
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
      EXPECT_EQ(p.steps(), 200) << testing::name_of(method);
    }
    // rk4/splitting4 at h = 1e-2 s: ~1e-5 rad over the first flip; exact: round-off.
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

/// A run of `method` at step dt (s) from s0, until it diverges (or t = 1000 s).
std::optional<Diverged> run_until_diverged(const RigidBodyModel& m, const BodyState& s0, Method method, double dt) {
  StepConfig cfg;
  cfg.method = method;
  cfg.dt = dt;
  Propagator p(m, s0, cfg);
  return run_until_diverged(p);
}

// Explicit Euler with a huge step on a fast spin: ω dt = 50 rad per step. The
// body (0.1, 1.9, 2.0) starts spinning about its major axis with a small tilt;
// Euler's orientation update rotates about ω by ~π per step and throws the spin
// towards the minor axis, multiplying the torque-free energy by up to I3/I1 = 20,
// which the guard reports (> 10×) — as a non-finite state would be.
TEST(Propagator, DivergingRunThrowsWithTimeStepBodyAndMethod) {
  const RigidBodyModel m = testing::body_with_moments({0.1, 1.9, 2.0}, 1.0, "spinning top");
  BodyState s0 = testing::spinning_state(m, Eigen::Quaterniond::Identity(), {3.0, 2.0, 50.0});
  const auto e = run_until_diverged(m, s0, Method::euler, 1.0);
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

// rk4 on a torque-free body is guarded in Euler's coordinates (check_free):
// at dt = 0.5 s a spin of |ω| ≈ 20 rad/s turns 10 rad per step, far beyond
// RK4's stability bound (2.83), so Π's energy grows geometrically.
TEST(Propagator, TorqueFreeRk4BlowUpThrowsInEulersCoordinates) {
  const RigidBodyModel m = testing::body_with_moments({1, 2, 3}, 1.0, "t-handle");
  const BodyState s0 = testing::spinning_state(m, Eigen::Quaterniond::Identity(), {0.5, 20.0, 0.5});
  const auto e = run_until_diverged(m, s0, Method::rk4, 0.5);
  ASSERT_TRUE(e) << "expected Diverged";
  const std::string what = e->what();
  EXPECT_NE(what.find("t-handle"), std::string::npos) << what;
  EXPECT_NE(what.find("method rk4"), std::string::npos) << what;
  EXPECT_GT(e->step_index, 0);
}

// Linear damping k/M = 100/s with dt = 1 s makes Euler multiply P by -99 per
// step: damping can only remove energy, so the balance trips.
TEST(Propagator, NonFiniteStateThrowsDiverged) {
  RigidBodyModel m = testing::body_with_moments({1, 2, 3}, 1.0, "damped");
  m.forces.terms.push_back(LinearDamping{100.0});
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

// Explicit Euler with angular_damping = 50 at dt = 0.5 s multiplies
// Π by (1 - 25/Iᵢ) per step (energy 1e237 at t = 10 s before the guard). The
// energy balance stops it within the first steps, naming time, step, body, method.
TEST(Propagator, DampedBlowUpOfAForcedBodyThrows) {
  RigidBodyModel m = testing::body_with_moments({1, 2, 3}, 1.0, "damped top");
  m.forces.terms.push_back(AngularDamping{50.0});
  const BodyState s0 = testing::spinning_state(m, Eigen::Quaterniond::Identity(), {0.5, 2, 0.5});
  StepConfig cfg;
  cfg.method = Method::euler;
  cfg.dt = 0.5;
  EXPECT_TRUE(coarse_step_warning(m, s0, cfg).has_value());
  Propagator p(m, s0, cfg);
  std::optional<Diverged> e;
  try {
    for (int k = 1; k <= 300; ++k) p.advance_to(k / 30.0);
  } catch (const Diverged& d) {
    e = d;
  }
  ASSERT_TRUE(e) << "expected Diverged";
  const std::string what = e->what();
  EXPECT_NE(what.find("damped top"), std::string::npos) << what;
  EXPECT_NE(what.find("euler"), std::string::npos) << what;
  EXPECT_LE(e->time, 2.0) << what;
  std::printf("%s\n", what.c_str());
  // The same body at a step that resolves the damping (dt k/I1 = 0.05) runs to the end.
  cfg.dt = 1e-3;
  EXPECT_FALSE(coarse_step_warning(m, s0, cfg).has_value());
  Propagator fine(m, s0, cfg);
  EXPECT_NO_THROW(fine.advance_to(10.0));
  EXPECT_LT(kinetic_energy(m, fine.state()), kinetic_energy(m, s0));
}

// A driven body is not flagged: a constant torque pumps energy in, and the
// balance credits its work (a thruster spinning a body up for 10 s).
TEST(Propagator, DrivenBodyPassesTheEnergyBalance) {
  for (Method method : {Method::euler, Method::rk4, Method::splitting}) {
    RigidBodyModel m = testing::body_with_moments({1, 2, 3}, 1.0, "driven");
    m.forces.terms.push_back(UniformGravity{Eigen::Vector3d(0, 0, -9.81)});
    m.forces.terms.push_back(PointForce{{0, 0, 20}, {1, 0, 0}, Frame::body});
    m.forces.terms.push_back(ConstantTorque{Eigen::Vector3d(0, 0, 5), Frame::world});
    const BodyState s0 = testing::spinning_state(m, Eigen::Quaterniond::Identity(), {0, 0, 0.1});
    StepConfig cfg;
    cfg.method = method;
    cfg.dt = 1e-2;
    Propagator p(m, s0, cfg);
    EXPECT_NO_THROW(p.advance_to(10.0)) << testing::name_of(method);
    EXPECT_GT(kinetic_energy(m, p.state()), 100 * kinetic_energy(m, s0)) << testing::name_of(method);
  }
}

// The trajectory of a fixed-step method does not depend on the
// sample times. Sampled at 7, 30 and 240 fps (and once at the end only), every
// fixed-step method reaches the same state at t = 10 s, bit for bit: the grid
// steps are the same operations; samples are partial steps off the grid.
TEST(Propagator, StateAt10sDoesNotDependOnTheFrameRate) {
  RigidBodyModel forced = testing::body_with_moments({1, 2, 3}, 2.0, "forced");
  forced.forces.terms.push_back(UniformGravity{Eigen::Vector3d(0, 0, -9.81)});
  forced.forces.terms.push_back(PointForce{{0.3, 0, 0}, {0, 0.2, 0}, Frame::body});
  forced.forces.terms.push_back(AngularDamping{0.05});
  for (const RigidBodyModel& m : {testing::reference_model(), forced}) {
    BodyState s0 = testing::reference_state(m);
    s0.P = {0.5, 0, 3};
    for (Method method : kAllMethods) {
      const MethodInfo& info = method_info(method);
      if (info.adaptive || (info.closed_form_if_free && m.forces.empty())) continue;
      StepConfig cfg;
      cfg.method = method;
      cfg.dt = 1e-2;
      Propagator once(m, s0, cfg);
      const BodyState end = once.advance_to(10.0);
      for (double fps : {7.0, 30.0, 240.0}) {
        Propagator p(m, s0, cfg);
        const long frames = std::lround(10.0 * fps);
        for (long k = 1; k <= frames; ++k) p.advance_to(static_cast<double>(k) / fps);
        const std::string where = testing::name_of(method) + " " + m.name + " fps " + std::to_string(fps);
        EXPECT_EQ(p.steps(), 1000) << where;
        EXPECT_EQ(p.state().q.coeffs(), end.q.coeffs()) << where;
        EXPECT_EQ(p.state().L, end.L) << where;
        EXPECT_EQ(p.state().c, end.c) << where;
        EXPECT_EQ(p.state().P, end.P) << where;
      }
    }
  }
}

// A sample between grid points is a partial step: within the method's error of
// the exact motion, and the next grid point is unaffected by it.
TEST(Propagator, SampleBetweenGridPointsIsAPartialStep) {
  const RigidBodyModel m = testing::reference_model();
  const BodyState s0 = testing::reference_state(m);
  const FreeRotationExact ex(m.inertia, s0.q, s0.L);
  StepConfig cfg;
  cfg.method = Method::rk4;
  cfg.dt = 1e-2;
  Propagator p(m, s0, cfg);
  const BodyState mid = p.advance_to(0.505);
  EXPECT_EQ(p.steps(), 50);
  EXPECT_EQ(p.time(), 0.505);
  EXPECT_LT(rotation_angle_between(mid.q, ex.orientation(0.505)), 1e-6);  // rk4 at 1e-2 s: 2.6e-7
  // The grid goes on as if the sample had not been taken: same bits as a run
  // that never stopped at 0.505 (rk4 carries (q, Π) and its round-off between
  // steps, so this is the test, not stateless step() calls).
  Propagator direct(m, s0, cfg);
  const BodyState a = p.advance_to(0.51), b = direct.advance_to(0.51);
  EXPECT_EQ(a.q.coeffs(), b.q.coeffs());
  EXPECT_EQ(a.L, b.L);
  // And the stateless step() chain agrees to round-off.
  EXPECT_LT(rotation_angle_between(a.q, testing::run_steps(Method::rk4, m, s0, 1e-2, 51).q), 1e-14);
}

}  // namespace
}  // namespace tumble
