// method = "auto" with a tolerance: whatever choose_method picks,
// and every candidate it calls usable, must meet the tolerance when run the way
// a scene runs it (stopping at every frame), checked against an independent
// reference (dop853 at rtol 1e-13), not against the pilot's own estimate.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "base/error.hpp"
#include "core/method_choice.hpp"
#include "core/propagator.hpp"
#include "reference_problem.hpp"
#include "test_helpers.hpp"

namespace tumble {
namespace {

// An asymmetric body (1, 2, 3) kg·m² near its middle axis, pushed by a
// body-fixed thruster and a body torque, under gravity: no closed form.
RigidBodyModel thruster_model() {
  RigidBodyModel m = testing::body_with_moments({1, 2, 3}, 1.0, "thruster");
  m.forces.terms.push_back(UniformGravity{Eigen::Vector3d(0, 0, -9.81)});
  m.forces.terms.push_back(PointForce{Eigen::Vector3d(0, 0, 2), Eigen::Vector3d(1, 0, 0), Frame::body});
  m.forces.terms.push_back(ConstantTorque{Eigen::Vector3d(0, 0.3, 0), Frame::body});
  return m;
}

BodyState thruster_state(const RigidBodyModel& m) {
  return testing::spinning_state(m, Eigen::Quaterniond::Identity(), {0.5, 3, 0.2});
}

// The run a scene makes: stop at every sample k·Δ (and at the end).
BodyState run_like_a_scene(const RigidBodyModel& m, const BodyState& s0, const StepConfig& cfg,
                           const ChoiceRequest& r) {
  Propagator p(m, s0, cfg);
  for (double k = 1; k * r.sample_interval < r.duration; ++k) p.advance_to(k * r.sample_interval);
  return p.advance_to(r.duration);
}

BodyState reference_end(const RigidBodyModel& m, const BodyState& s0, double duration) {
  StepConfig cfg;
  cfg.method = Method::dop853;
  cfg.rtol = 1e-13;
  cfg.atol = 1e-16;
  return Propagator(m, s0, cfg).advance_to(duration);
}

// The pilot trusts an extrapolation only where the observed order is the
// method's own, within 0.4: an order-2 method whose differences shrink by
// 2^1.5 (still pre-asymptotic) or 2^2.5 is not there yet, nor is a NaN
// (a difference at round-off).
TEST(MethodChoice, ThePilotsOrderWindowIsTheMethodsOrderWithinFourTenths) {
  EXPECT_TRUE(order_seen(2.0, 2));
  EXPECT_TRUE(order_seen(2.35, 2));
  EXPECT_TRUE(order_seen(1.65, 2));
  EXPECT_TRUE(order_seen(3.7, 4));
  EXPECT_FALSE(order_seen(1.5, 2));
  EXPECT_FALSE(order_seen(2.5, 2));
  EXPECT_FALSE(order_seen(4.5, 4));
  EXPECT_FALSE(order_seen(std::nan(""), 2));
  EXPECT_FALSE(order_seen(INFINITY, 2));
}

TEST(MethodChoice, TorqueFreeBodyGetsTheClosedForm) {
  const RigidBodyModel m = testing::reference_model();
  const MethodChoice c = choose_method(m, testing::reference_state(m), {10, 1.0 / 30, 1e-9});
  EXPECT_EQ(c.config.method, Method::exact);
  EXPECT_TRUE(c.candidates.empty());
  EXPECT_NE(c.reason.find("torque-free"), std::string::npos) << c.reason;
}

// Under gravity alone the rotation is free and the kicks are exact, so `exact`
// is right at any step: its runs agree to round-off, no order shows, and it
// must still qualify (at the coarsest step) and, in a scene, win.
TEST(MethodChoice, ExactWithKicksWinsUnderGravityAlone) {
  RigidBodyModel m = testing::body_with_moments({1, 2, 3}, 0.5, "thrown");
  m.forces.terms.push_back(UniformGravity{Eigen::Vector3d(0, 0, -9.81)});
  BodyState s0 = testing::spinning_state(m, Eigen::Quaterniond::Identity(), {2, 9, 1});
  s0.P = m.mass * Eigen::Vector3d(0.8, 0, 8.8);
  ChoiceRequest r{1.8, 1.0 / 30, 1e-9};
  const MethodChoice c = choose_method(m, s0, r);
  EXPECT_EQ(c.config.method, Method::exact) << c.reason;
  const double err = end_state_error(m, run_like_a_scene(m, s0, c.config, r), reference_end(m, s0, r.duration));
  EXPECT_LE(err, r.tolerance) << c.reason;
  // Every candidate measured: exact qualifies at the ladder's coarsest step.
  r.prune = false;
  const MethodChoice all = choose_method(m, s0, r);
  bool exact_usable = false;
  for (const MethodEstimate& e : all.candidates)
    if (e.method == Method::exact) {
      exact_usable = e.usable;
      EXPECT_EQ(e.config.dt, r.duration / 64) << e.note;
    }
  EXPECT_TRUE(exact_usable);
}

TEST(MethodChoice, EveryUsableCandidateMeetsTheTolerance) {
  const RigidBodyModel m = thruster_model();
  const BodyState s0 = thruster_state(m);
  const ChoiceRequest base{5, 1.0 / 30, 1e-6};
  const BodyState ref = reference_end(m, s0, base.duration);
  for (double tol : {1e-3, 1e-6, 1e-8}) {
    ChoiceRequest r = base;
    r.tolerance = tol;
    r.prune = false;
    const MethodChoice c = choose_method(m, s0, r);
    // The scenes' pick (prune: the adaptive pair, no pilot) meets the tolerance too.
    r.prune = true;
    const MethodChoice pruned = choose_method(m, s0, r);
    EXPECT_TRUE(method_info(pruned.config.method).adaptive) << pruned.reason;
    EXPECT_LE(end_state_error(m, run_like_a_scene(m, s0, pruned.config, r), ref), tol) << pruned.reason;
    r.prune = false;
    int usable = 0;
    for (const MethodEstimate& e : c.candidates) {
      if (!e.usable) continue;
      ++usable;
      const double err = end_state_error(m, run_like_a_scene(m, s0, e.config, r), ref);
      EXPECT_LE(err, tol) << method_name(e.method) << " at tolerance " << tol << " (dt " << e.config.dt
                          << ", predicted " << e.error << ")";
      // The prediction is an estimate, not a bound; it should still be the right size.
      if (!method_info(e.method).adaptive) {
        EXPECT_GT(err, e.error / 30) << method_name(e.method) << " at " << tol;
      }
      if (std::getenv("TUMBLE_VERBOSE")) std::printf("%-18s tol %.0e dt %.3g steps %.0f predicted %.2e actual %.2e\n", std::string(method_name(e.method)).c_str(), tol, e.config.dt, e.steps, e.error, err);
    }
    EXPECT_GE(usable, 3) << "tolerance " << tol;
    // The pick is the cheapest usable candidate, and it is usable.
    for (const MethodEstimate& e : c.candidates)
      if (e.usable) {
        EXPECT_LE(c.cost_s, e.cost_s) << method_name(e.method);
      }
    EXPECT_LE(c.error, tol);
    EXPECT_NE(c.reason.find(std::string(method_name(c.config.method))), std::string::npos) << c.reason;
  }
}

// A symmetric top under a world torque and angular damping (the bench's torqued
// top): its closed form is trigonometric, so `exact` with kicks steps cheaply,
// and at a loose tolerance it beats the pair; its error model is measured on a
// window and extrapolated, so the pick is checked against the reference here.
TEST(MethodChoice, TorquedSymmetricTopTakesExactWithKicksWhenLoose) {
  RigidBodyModel m = testing::body_with_moments({2, 2, 4}, 1.0, "torqued_top");
  m.forces.terms.push_back(ConstantTorque{Eigen::Vector3d(0.5, 0, 0), Frame::world});
  m.forces.terms.push_back(AngularDamping{0.02});
  const BodyState s0 = testing::spinning_state(m, Eigen::Quaterniond::Identity(), {3, 1, 5});
  const ChoiceRequest r{10, 0, 1e-3};
  const BodyState ref = reference_end(m, s0, r.duration);
  const MethodChoice loose = choose_method(m, s0, r);
  EXPECT_EQ(loose.config.method, Method::exact) << loose.reason;
  ASSERT_EQ(loose.candidates.size(), 2u);
  EXPECT_GT(loose.candidates[0].cost_s, loose.cost_s);  // the pair was priced, and costs more
  const double err = end_state_error(m, Propagator(m, s0, loose.config).advance_to(r.duration), ref);
  EXPECT_LE(err, r.tolerance) << loose.reason;
  EXPECT_GT(err, r.tolerance / 30) << loose.reason;  // the bound is the right size, not wasteful
  // Tight: order 2 loses to the pair, and the probe says why.
  const MethodChoice tight = choose_method(m, s0, {10, 0, 1e-8});
  EXPECT_EQ(tight.config.method, Method::dop853) << tight.reason;
  ASSERT_EQ(tight.candidates.size(), 2u);
  EXPECT_FALSE(tight.candidates[1].usable);
  EXPECT_NE(tight.candidates[1].note.find("priced above the pair"), std::string::npos) << tight.candidates[1].note;
}

// The elliptic closed form costs about a pair's step: on a triaxial body `exact`
// with kicks is not even probed, and the pair is not priced.
TEST(MethodChoice, TriaxialTorquedBodyGetsThePairUnpriced) {
  const RigidBodyModel m = thruster_model();
  const MethodChoice c = choose_method(m, thruster_state(m), {5, 1.0 / 30, 1e-3});
  ASSERT_EQ(c.candidates.size(), 1u);
  EXPECT_EQ(c.config.method, Method::dop853);
  EXPECT_EQ(c.candidates[0].steps, 0);
}

TEST(MethodChoice, TighterToleranceNeverTakesFewerSteps) {
  const RigidBodyModel m = thruster_model();
  const BodyState s0 = thruster_state(m);
  const MethodChoice loose = choose_method(m, s0, {5, 1.0 / 30, 1e-4, false});
  const MethodChoice tight = choose_method(m, s0, {5, 1.0 / 30, 1e-8, false});
  ASSERT_EQ(loose.candidates.size(), tight.candidates.size());
  for (size_t i = 0; i < loose.candidates.size(); ++i) {
    const MethodEstimate &a = loose.candidates[i], &b = tight.candidates[i];
    if (!a.usable || !b.usable) continue;
    EXPECT_LE(a.steps, b.steps) << method_name(a.method);
    EXPECT_GE(a.cost_s, 0);
  }
  EXPECT_GE(tight.cost_s, loose.cost_s);
}

// The order check must hold on what the pilot saw: a 2nd-order method must not
// be credited with 4th order and vice versa.
TEST(MethodChoice, ObservedOrdersMatchTheMethods) {
  const RigidBodyModel m = thruster_model();
  const MethodChoice c = choose_method(m, thruster_state(m), {5, 1.0 / 30, 1e-7, false});
  for (const MethodEstimate& e : c.candidates) {
    if (!e.usable || method_info(e.method).adaptive || e.observed_order == 0) continue;
    const int p = e.method == Method::exact ? 2 : method_order(e.method);
    EXPECT_NEAR(e.observed_order, p, 0.4) << method_name(e.method);
  }
}

TEST(MethodChoice, EndStateErrorCountsShiftInRadiiOfGyration) {
  const RigidBodyModel m = testing::body_with_moments({1, 2, 3}, 2.0);  // r_g = sqrt(6 / 4)
  BodyState a, b;
  b.c = {0, 0, std::sqrt(1.5) * 1e-3};
  EXPECT_NEAR(end_state_error(m, a, b), 1e-3, 1e-15);
  b.c.setZero();
  b.q = Eigen::Quaterniond(Eigen::AngleAxisd(2e-3, Eigen::Vector3d::UnitY()));
  EXPECT_NEAR(end_state_error(m, a, b), 2e-3, 1e-15);
}

// The auto policy without a tolerance, in core alone (scenes only read it):
// the closed form for a torque-free body; otherwise the step asked for, whose
// default method is StepConfig's, which is what a scene without `method` gets.
TEST(AutoWithoutTolerance, ClosedFormOnlyWhenTorqueFree) {
  StepConfig asked;
  asked.dt = 0.02;
  const RigidBodyModel free = testing::body_with_moments({1, 2, 3}, 1.0, "free");
  ASSERT_TRUE(auto_takes_closed_form(free));
  const MethodChoice f = auto_without_tolerance(free, asked);
  EXPECT_EQ(f.config.method, Method::exact);
  EXPECT_EQ(f.config.dt, 0.02);
  EXPECT_EQ(f.reason, "exact: torque-free, closed form");
  EXPECT_TRUE(f.candidates.empty());

  const RigidBodyModel pushed = thruster_model();
  ASSERT_FALSE(auto_takes_closed_form(pushed));
  const MethodChoice p = auto_without_tolerance(pushed, asked);
  EXPECT_EQ(p.config.method, Method::splitting);
  EXPECT_EQ(p.config.method, StepConfig{}.method);
  EXPECT_EQ(p.config.dt, 0.02);
  EXPECT_EQ(p.reason, "splitting: has forces (no tolerance given)");
  // With a tolerance the torque-free body is not measured either.
  EXPECT_EQ(choose_method(free, testing::spinning_state(free, Eigen::Quaterniond::Identity(), {0.1, 3, 0.1}),
                          {2, 1.0 / 30, 1e-6})
                .config.method,
            Method::exact);
}

}  // namespace
}  // namespace tumble
