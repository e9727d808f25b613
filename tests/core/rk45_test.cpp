// Adaptive Dormand–Prince through Propagator: the global orientation error
// against the exact solution falls as rtol falls and stays within 100 × rtol;
// dense output at sample times does not perturb the step sequence.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/free_rotation_exact.hpp"
#include "core/propagator.hpp"
#include "core/quaternion.hpp"
#include "core/rk45.hpp"
#include "reference_problem.hpp"
#include "test_helpers.hpp"

namespace tumble {
namespace {

double rk45_error(const RigidBodyModel& m, const BodyState& s0, double t_end, double rtol) {
  StepConfig cfg;
  cfg.method = Method::rk45;
  cfg.rtol = rtol;
  cfg.atol = 1e-3 * rtol;
  Propagator p(m, s0, cfg);
  const BodyState s = p.advance_to(t_end);
  return rotation_angle_between(s.q, FreeRotationExact(m.inertia, s0.q, s0.L).orientation(t_end));
}

void check_tolerance_proportionality(const RigidBodyModel& m, const BodyState& s0, double t_end) {
  double prev = INFINITY;
  for (double rtol : {1e-5, 1e-7, 1e-9, 1e-11}) {
    const double e = rk45_error(m, s0, t_end, rtol);
    std::printf("rk45 t_end=%g rtol=%.0e: error %.3e rad (%.2f x rtol)\n", t_end, rtol, e, e / rtol);
    EXPECT_LT(e, prev) << "rtol=" << rtol;
    EXPECT_LT(e, 100 * rtol) << "rtol=" << rtol;
    prev = e;
  }
}

TEST(Rk45, ErrorFallsWithRtolReferenceProblem) {
  const RigidBodyModel m = testing::reference_model();
  check_tolerance_proportionality(m, testing::reference_state(m), 1.0);
}

TEST(Rk45, ErrorFallsWithRtolGenericBody) {
  const RigidBodyModel m = testing::body_with_moments({0.7, 1.3, 2.2});
  const BodyState s0 = testing::spinning_state(m, Eigen::Quaterniond(0.3, -0.5, 0.7, 0.2), {0.3, 0.5, 4.0});
  check_tolerance_proportionality(m, s0, 10.0);
}

// Sampling many times in between must not change where the integrator ends up
// (dense output never shortens a step), and every sample is accurate.
TEST(Rk45, DenseOutputDoesNotPerturbSteps) {
  const RigidBodyModel m = testing::reference_model();
  const BodyState s0 = testing::reference_state(m);
  Rk45Options o;
  o.rtol = 1e-10;
  o.atol = 1e-13;
  Rk45 direct(m, s0, 0.0, o), sampled(m, s0, 0.0, o);
  const FreeRotationExact ex(m.inertia, s0.q, s0.L);
  for (int k = 1; k <= 60; ++k) {
    const double t = k / 60.0;
    const BodyState s = sampled.advance_to(t);
    EXPECT_LT(rotation_angle_between(s.q, ex.orientation(t)), 1e-7) << "t=" << t;
  }
  const BodyState a = direct.advance_to(1.0), b = sampled.advance_to(1.0);
  EXPECT_EQ(direct.accepted(), sampled.accepted());
  EXPECT_EQ(a.q.coeffs(), b.q.coeffs());
  EXPECT_EQ(a.L, b.L);
}

}  // namespace
}  // namespace tumble
