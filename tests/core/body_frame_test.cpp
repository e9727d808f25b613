// Euler's coordinates: on the reference problem
// (moments 1, 2, 3; ω_body = (0.01, 10, 0.01) rad/s; 10 s, three flips) rk4
// and rk45 in (c, q, P, Π) stay close to the closed form where the seed's
// coordinates lose the flip times. Errors are against FreeRotationExact.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "core/body_frame.hpp"
#include "core/fixed_stepper.hpp"
#include "core/methods/free_rotation_exact.hpp"
#include "core/propagator.hpp"
#include "core/quaternion.hpp"
#include "reference_problem.hpp"
#include "test_helpers.hpp"

namespace tumble {
namespace {

double error_at_10s(Method method, double dt) {
  const RigidBodyModel m = testing::reference_model();
  const BodyState s0 = testing::reference_state(m);
  const FreeRotationExact ex(m.inertia, s0.q, s0.L);
  const BodyState s = integrate_fixed(method, m, s0, 0.0, dt, std::lround(10.0 / dt));  // as a run steps
  return rotation_angle_between(s.q, ex.orientation(10.0));
}

TEST(BodyFrame, Rk4OnTheReferenceProblem) {
  const double body = error_at_10s(Method::rk4, 1e-3), seed = error_at_10s(Method::rk4_seed, 1e-3);
  std::printf("dt = 1e-3, t = 10 s: rk4 (Euler's coordinates) %.3e rad, rk4_seed %.3e rad\n", body, seed);
  EXPECT_LE(body, 1e-8);
  // The seed's coordinates: the flip times move (docs/methods.md: 1.57e-3).
  EXPECT_GT(seed, 1e3 * body);
}

// A run carries (q, Π) from step to step (Propagator, MethodInfo::coords_step),
// so its error at dt = 1 ms is RK4's truncation error: 8.89e-10 rad, measured
// with the same steps in __float128 (a 1e-15 change of L cannot
// move the closed form by more than ~1e-13 rad here). Stepping the seed's
// state (q, L_world) through step() rounds Π = q̄ L afresh each step: Π₁ and Π₃
// (~0.01) then take round-off of |L| (~20), and near the separatrix that spread
// the error over 2e-9 … 2.5e-8 rad for the same perturbations.
TEST(BodyFrame, Rk4RunIsTruncationLimitedNotRoundOffLimited) {
  const RigidBodyModel m = testing::reference_model();
  double worst_run = 0, worst_stateless = 0;
  for (int k = 0; k < 8; ++k) {
    BodyState s0 = testing::reference_state(m);
    s0.L.y() *= 1 + k * 1e-15;
    const FreeRotationExact ex(m.inertia, s0.q, s0.L);
    Propagator p(m, s0, StepConfig{Method::rk4, 1e-3});
    worst_run = std::max(worst_run, rotation_angle_between(p.advance_steps(10000).q, ex.orientation(10.0)));
    const BodyState s = testing::run_steps(Method::rk4, m, s0, 1e-3, 10000);
    worst_stateless = std::max(worst_stateless, rotation_angle_between(s.q, ex.orientation(10.0)));
  }
  std::printf("rk4, dt = 1e-3, 8 perturbed starts: worst run %.3e rad, worst stateless step() chain %.3e rad\n",
              worst_run, worst_stateless);
  EXPECT_LE(worst_run, 1.5e-9);
  EXPECT_GE(worst_run, 5e-10);  // the truncation error is there: RK4 is not exact
}

TEST(BodyFrame, Rk45AtRtol1e9OnTheReferenceProblem) {
  const RigidBodyModel m = testing::reference_model();
  const BodyState s0 = testing::reference_state(m);
  const FreeRotationExact ex(m.inertia, s0.q, s0.L);
  StepConfig cfg;
  cfg.method = Method::rk45;
  cfg.rtol = 1e-9;
  cfg.dt = 10;
  Propagator p(m, s0, cfg);
  const double e = rotation_angle_between(p.advance_to(10.0).q, ex.orientation(10.0));
  std::printf("rk45 rtol 1e-9: %.3e rad in %ld steps\n", e, p.steps());
  EXPECT_LE(e, 1e-6);
}

// The conversion is exact up to round-off both ways, and the state the rest of
// tumble sees is the seed's: unit q and world L.
TEST(BodyFrame, CoordinatesRoundTrip) {
  const RigidBodyModel m = testing::body_with_moments({1, 2, 3});
  BodyState s = testing::spinning_state(m, Eigen::Quaterniond(0.3, -0.5, 0.7, 0.2), {1, -4, 2});
  s.c = {1, 2, 3};
  s.P = {-1, 0.5, 2};
  const BodyState back = from_body_coords(to_body_coords(s));
  EXPECT_LT((back.L - s.L).norm(), 1e-15 * s.L.norm());
  EXPECT_LT(rotation_angle_between(back.q, s.q), 1e-15);
  EXPECT_EQ(back.c, s.c);
  EXPECT_EQ(back.P, s.P);
}

// Under a torque the body-frame rate adds q̄ τ to Π' and is the seed's
// derivative in other coordinates: d(qΠ)/dt = L' = τ.
TEST(BodyFrame, RateIsTheSeedDerivative) {
  RigidBodyModel m = testing::body_with_moments({1, 2, 3});
  m.forces.terms.push_back(UniformGravity{Eigen::Vector3d(0, 0, -9.81)});
  m.forces.terms.push_back(ConstantTorque{Eigen::Vector3d(0.3, -0.2, 0.5), Frame::world});
  m.forces.terms.push_back(AngularDamping{0.1});
  const BodyState s = testing::spinning_state(m, Eigen::Quaterniond(0.3, -0.5, 0.7, 0.2), {1, -4, 2});
  const BodyCoords x = to_body_coords(s);
  const BodyRate r = body_rate(m, x, 0);
  const Derivative d = derivative(m, s, 0);
  Eigen::Quaterniond dq;
  dq.coeffs() = r.dq;
  // L' = q' Π + q Π' with q' Π = ω_world × L for a unit q.
  const Eigen::Vector3d dL = s.q * r.dpi + omega_world(m, s).cross(s.L);
  EXPECT_LT((dL - d.dL).norm(), 1e-14 * (1 + d.dL.norm() + s.L.norm()));
  EXPECT_LT((r.dq - d.dq).norm(), 1e-14 * (1 + d.dq.norm()));
  EXPECT_EQ(r.dP, d.dP);
}

}  // namespace
}  // namespace tumble
