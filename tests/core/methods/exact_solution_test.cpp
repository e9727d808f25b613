#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/dynamics.hpp"
#include "core/methods/free_rotation_exact.hpp"
#include "core/integrator.hpp"
#include "core/propagator.hpp"
#include "core/quaternion.hpp"
#include "test_helpers.hpp"
#include "reference_problem.hpp"

namespace tumble {
namespace {

// Reference: RK4 at a tiny step; the exact solution must agree to ~1e-10.
BodyState rk4_fine(const RigidBodyModel& m, BodyState s, double t_end, double h) {
  const long n = static_cast<long>(std::llround(t_end / h));
  for (long i = 0; i < n; ++i) s = step(Method::rk4, m, s, i * h, h);
  return s;
}

TEST(ExactSolution, MatchesFineRk4OnReferenceProblem) {
  const RigidBodyModel m = testing::reference_model();
  const BodyState s0 = testing::reference_state(m);
  const FreeRotationExact ex(m.inertia, s0.q, s0.L);
  BodyState s = s0;
  for (int k = 1; k <= 4; ++k) {
    s = rk4_fine(m, s, 0.5, 1e-5);
    const double t = 0.5 * k;
    EXPECT_LT(rotation_angle_between(s.q, ex.orientation(t)), 1e-9) << "t=" << t;
    EXPECT_LT((momentum_body(s) - ex.momentum_body(t)).norm(), 1e-8) << "t=" << t;
  }
}

// A generic asymmetric body in both regimes (near the major and the minor axis),
// with an arbitrary initial orientation.
TEST(ExactSolution, MatchesFineRk4BothRegimes) {
  for (const Eigen::Vector3d& w : {Eigen::Vector3d(0.3, 0.5, 4.0), Eigen::Vector3d(5.0, 0.7, -0.4),
                                  Eigen::Vector3d(-1.0, 2.0, -3.0)}) {
    RigidBodyModel m;
    m.inertia = {0.7, 1.3, 2.2};
    m.inv_inertia = m.inertia.cwiseInverse();
    BodyState s0;
    s0.q = Eigen::Quaterniond(0.3, -0.5, 0.7, 0.2).normalized();
    s0.L = s0.q * m.inertia.cwiseProduct(w);
    const FreeRotationExact ex(m.inertia, s0.q, s0.L);
    const BodyState s = rk4_fine(m, s0, 2.0, 1e-5);
    EXPECT_LT(rotation_angle_between(s.q, ex.orientation(2.0)), 1e-9) << w.transpose();
  }
}

// The closed form must be as well conditioned as the motion itself. Over
// t ≤ 1e-3 s two solutions whose initial orientations differ by δ separate by at
// most δ·e^{λt} (λ = Ω2·√((I2-I1)(I3-I2)/(I1 I3)) ≈ 5.8/s here, so ≤ 1.006 δ), plus
// round-off. The reference state sits 5e-7 (relative) from the separatrix, where
// k → 1 and 1 - k² sin²φ cancels; evaluating it that way cost ~1e-11 rad.
TEST(ExactSolution, ContinuousInInitialStateNearSeparatrix) {
  const RigidBodyModel m = testing::reference_model();
  const BodyState s0 = testing::reference_state(m);
  const FreeRotationExact ex(m.inertia, s0.q, s0.L);
  const double delta = 1e-14;
  for (int axis = 0; axis < 3; ++axis) {
    Eigen::Vector3d v = Eigen::Vector3d::Zero();
    v[axis] = delta;
    const FreeRotationExact perturbed(m.inertia, quat_exp(v) * s0.q, s0.L);
    for (double t : {1e-9, 1e-6, 1e-3}) {
      EXPECT_LT(rotation_angle_between(perturbed.orientation(t), ex.orientation(t)), 2 * delta + 1e-15)
          << "axis " << axis << " t=" << t;
    }
  }
}

// Semigroup property: restarting the closed form from its own state at t and
// advancing h lands on the solution at t + h. The exact flow amplifies an error
// by at most e^{λh} ≈ 1.8 over h = 0.1 s, so the mismatch must stay at the
// round-off of evaluating the solution (≈ (|φ| + |τ|)·ε ≈ 1e-13 rad at t ≤ 10 s).
TEST(ExactSolution, RestartsComposeToRoundOffOnReferenceProblem) {
  const RigidBodyModel m = testing::reference_model();
  const BodyState s0 = testing::reference_state(m);
  const FreeRotationExact ex(m.inertia, s0.q, s0.L);
  const double h = 0.1;
  double worst = 0;
  for (int i = 0; i < 100; ++i) {
    const double t = i * h;
    const FreeRotationExact restart(m.inertia, ex.orientation(t), s0.L);
    worst = std::max(worst, rotation_angle_between(restart.orientation(h), ex.orientation(t + h)));
  }
  EXPECT_LT(worst, 1e-12);
}

// `exact` is round-off accurate at any step size: exact_step repeated with
// dt = 0.1, 0.5, 1 s, and Propagator(Method::exact) sampled anywhere, agree with
// the closed form from t = 0. The reference problem is checked over 1 s (before
// its first flip; near the separatrix round-off itself grows as e^{5.8 t}); a
// body far from the separatrix, in both regimes, over 10 s.
TEST(ExactMethod, RoundOffAtAnyStepSize) {
  struct Case {
    RigidBodyModel m;
    BodyState s0;
    double t_end;
  };
  std::vector<Case> cases;
  {
    const RigidBodyModel m = testing::reference_model();
    cases.push_back({m, testing::reference_state(m), 1.0});
  }
  for (const Eigen::Vector3d& w : {Eigen::Vector3d(0.3, 0.5, 4.0), Eigen::Vector3d(5.0, 0.7, -0.4)}) {
    const RigidBodyModel m = testing::body_with_moments({0.7, 1.3, 2.2});
    cases.push_back({m, testing::spinning_state(m, Eigen::Quaterniond(0.3, -0.5, 0.7, 0.2), w), 10.0});
  }
  for (const Case& c : cases) {
    const FreeRotationExact ex(c.m.inertia, c.s0.q, c.s0.L);
    for (double dt : {0.1, 0.5, 1.0}) {
      const long n = std::lround(c.t_end / dt);
      const BodyState s = testing::run_steps(Method::exact, c.m, c.s0, dt, n);
      EXPECT_LT(rotation_angle_between(s.q, ex.orientation(c.t_end)), 1e-12) << "dt=" << dt;
      EXPECT_EQ(s.L, c.s0.L);  // torque-free: L is never touched
    }
    for (double dt : {1e-3, 0.1, 1.0}) {
      StepConfig cfg;
      cfg.method = Method::exact;
      cfg.dt = dt;
      Propagator p(c.m, c.s0, cfg);
      for (double t : {0.37, 0.5, 1.0, c.t_end}) {
        if (t > c.t_end) continue;
        const BodyState& s = p.advance_to(t);
        EXPECT_LT(rotation_angle_between(s.q, ex.orientation(t)), 1e-12) << "dt=" << dt << " t=" << t;
      }
    }
  }
}

// Symmetric and spherical bodies use their own closed forms: check them against
// fine RK4 like the asymmetric one.
TEST(ExactSolution, SymmetricAndSphericalBodiesMatchFineRk4) {
  for (const Eigen::Vector3d& inertia :
       {Eigen::Vector3d(1.0, 1.0, 2.5), Eigen::Vector3d(0.4, 1.5, 1.5), Eigen::Vector3d(2.0, 2.0, 2.0)}) {
    const RigidBodyModel m = testing::body_with_moments(inertia);
    const BodyState s0 = testing::spinning_state(m, Eigen::Quaterniond(0.9, 0.1, -0.3, 0.2), {1.5, -0.8, 3.0});
    const FreeRotationExact ex(m.inertia, s0.q, s0.L);
    const BodyState s = rk4_fine(m, s0, 2.0, 1e-4);
    EXPECT_LT(rotation_angle_between(s.q, ex.orientation(2.0)), 1e-9) << inertia.transpose();
    EXPECT_LT((momentum_body(s) - ex.momentum_body(2.0)).norm(), 1e-9) << inertia.transpose();
  }
}

// On and at the separatrix: a spin about the intermediate axis (an unstable
// equilibrium: it must keep spinning at Π2/I2, not stop or precess at another
// rate), and a state on the separatrix (l² = 2E·I2, k = 1: the non-periodic
// branch) checked against fine RK4 while it leaves the unstable axis.
TEST(ExactSolution, IntermediateAxisSpinAndSeparatrix) {
  const RigidBodyModel m = testing::body_with_moments({1, 2, 3});
  const Eigen::Quaterniond q0 = Eigen::Quaterniond(0.8, 0.2, -0.4, 0.4).normalized();
  for (int n = 0; n < 20; ++n) {  // several orientations: different round-off off the axis
    const Eigen::Quaterniond qn = q0 * axis_rotation(1, 0.37 * n);
    const BodyState s = testing::spinning_state(m, qn, {0, 2.0, 0});
    const FreeRotationExact ex(m.inertia, s.q, s.L);
    for (double t : {0.05, 0.5, 1.5}) {
      EXPECT_LT(rotation_angle_between(ex.orientation(t), qn * axis_rotation(1, 2.0 * t)), 1e-12)
          << "n=" << n << " t=" << t;
    }
  }
  // Π = (a, b, √3 a) with I = (1, 2, 3): Π1²(1/I1 - 1/I2) = Π3²(1/I2 - 1/I3), so 2E·I2 = l².
  const double a = 0.2;
  BodyState s0;
  s0.q = q0;
  s0.L = q0 * Eigen::Vector3d(a, 3.0, std::sqrt(3.0) * a);
  const FreeRotationExact ex(m.inertia, s0.q, s0.L);
  BodyState s = s0;
  for (int k = 1; k <= 4; ++k) {
    s = rk4_fine(m, s, 0.5, 1e-5);
    EXPECT_LT(rotation_angle_between(s.q, ex.orientation(0.5 * k)), 1e-9) << "t=" << 0.5 * k;
  }
}

}  // namespace
}  // namespace tumble
