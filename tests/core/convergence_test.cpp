// Every fixed-step method converges to the exact torque-free solution at its
// stated order. Orientation errors at dt, dt/2, dt/4 give two measured orders
// log2(e(dt)/e(dt/2)) and log2(e(dt/2)/e(dt/4)); both must lie within 0.2 of the
// expected order. The reference problem over 1 s (before the first flip; the
// adaptive pairs' uncontrolled steps over 2 s), with dt chosen per method so
// that the errors are asymptotic yet ≥ 5e-11 rad, far above the ~1e-13 rad
// round-off of the closed form and the ~2e-12 rad of step()'s conversions.
#include <gtest/gtest.h>

#include <cmath>

#include "core/methods/free_rotation_exact.hpp"
#include "core/integrator.hpp"
#include "core/quaternion.hpp"
#include "reference_problem.hpp"
#include "test_helpers.hpp"

namespace tumble {
namespace {

struct OrderCase {
  Method method;
  double expected_order;
  double dt;  // coarsest step, s
  double t_end = 1.0;  // s
};

class Convergence : public ::testing::TestWithParam<OrderCase> {};

TEST_P(Convergence, MeasuredOrderMatchesExpected) {
  const OrderCase c = GetParam();
  const RigidBodyModel m = testing::reference_model();
  const BodyState s0 = testing::reference_state(m);
  const double t_end = c.t_end;
  const FreeRotationExact ex(m.inertia, s0.q, s0.L);
  const Eigen::Quaterniond q_exact = ex.orientation(t_end);
  double err[3];
  for (int k = 0; k < 3; ++k) {
    const double dt = c.dt / (1 << k);
    const BodyState s = testing::run_steps(c.method, m, s0, dt, std::lround(t_end / dt));
    err[k] = rotation_angle_between(s.q, q_exact);
  }
  const double p1 = std::log2(err[0] / err[1]), p2 = std::log2(err[1] / err[2]);
  RecordProperty("errors", ::testing::PrintToString(std::vector<double>{err[0], err[1], err[2]}));
  RecordProperty("orders", ::testing::PrintToString(std::vector<double>{p1, p2}));
  std::printf("%-20s dt=%g: errors %.3e %.3e %.3e rad, orders %.3f %.3f (expected %g)\n",
              testing::name_of(c.method).c_str(), c.dt, err[0], err[1], err[2], p1, p2, c.expected_order);
  EXPECT_GT(err[2], 5e-11) << "errors too close to round-off to measure an order";
  EXPECT_NEAR(p1, c.expected_order, 0.2);
  EXPECT_NEAR(p2, c.expected_order, 0.2);
}

// The adaptive pairs by their uncontrolled steps (MethodInfo::step).
INSTANTIATE_TEST_SUITE_P(FixedStepMethods, Convergence,
                         ::testing::Values(OrderCase{Method::euler, 1, 1e-3},
                                           OrderCase{Method::semi_implicit_euler, 1, 1e-3},
                                           OrderCase{Method::rk4, 4, 4e-2},
                                           OrderCase{Method::rk4_seed, 4, 1e-2},
                                           OrderCase{Method::implicit_midpoint, 2, 1e-2},
                                           OrderCase{Method::splitting, 2, 1e-2},
                                           OrderCase{Method::splitting4, 4, 1e-2},
                                           OrderCase{Method::rk45, 5, 2e-2, 2.0},
                                           OrderCase{Method::dop853, 8, 2e-1, 2.0}),
                         [](const auto& info) { return testing::name_of(info.param.method); });

// The orders the interface reports are the ones the tests measure.
TEST(Convergence, MethodOrderTable) {
  EXPECT_EQ(method_order(Method::euler), 1);
  EXPECT_EQ(method_order(Method::semi_implicit_euler), 1);
  EXPECT_EQ(method_order(Method::rk4), 4);
  EXPECT_EQ(method_order(Method::rk4_seed), 4);
  EXPECT_EQ(method_order(Method::implicit_midpoint), 2);
  EXPECT_EQ(method_order(Method::splitting), 2);
  EXPECT_EQ(method_order(Method::splitting4), 4);
  EXPECT_EQ(method_order(Method::rk45), 5);
  EXPECT_EQ(method_order(Method::dop853), 8);
}

}  // namespace
}  // namespace tumble
