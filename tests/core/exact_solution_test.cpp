#include <gtest/gtest.h>

#include "core/dynamics.hpp"
#include "core/free_rotation_exact.hpp"
#include "core/integrator.hpp"
#include "core/quaternion.hpp"
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

}  // namespace
}  // namespace tumble
