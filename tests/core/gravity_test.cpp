// Uniform gravity: the centre of mass follows the exact parabola
// c(t) = c0 + v0 t + ½ g t², P(t) = M (v0 + g t). Velocity Verlet-type Strang
// splittings (splitting, splitting4, implicit_midpoint, exact) and RK4 are exact
// for a constant force, so they match to round-off. Explicit Euler lags by
// exactly ½ g T h (c_N = c0 + v0 T + g h² N(N-1)/2), semi-implicit Euler leads
// by ½ g T h: first order, with the error known in closed form.
// Gravity has no torque, so the rotation stays the free one.
#include <gtest/gtest.h>

#include <cmath>

#include "core/methods/free_rotation_exact.hpp"
#include "core/integrator.hpp"
#include "core/propagator.hpp"
#include "core/quaternion.hpp"
#include "test_helpers.hpp"

namespace tumble {
namespace {

const Eigen::Vector3d kG(0.3, -0.2, -9.81);
const Eigen::Vector3d kC0(0.5, -1.0, 2.0), kV0(1.0, 2.0, 3.0);
constexpr double kT = 2.0;

RigidBodyModel gravity_body() {
  RigidBodyModel m = testing::body_with_moments({0.7, 1.3, 2.2}, 2.5, "falling");
  m.forces.terms.push_back(UniformGravity{kG});
  return m;
}

BodyState initial(const RigidBodyModel& m) {
  BodyState s = testing::spinning_state(m, Eigen::Quaterniond(0.3, -0.5, 0.7, 0.2), {0.3, 0.5, 4.0});
  s.c = kC0;
  s.P = m.mass * kV0;
  return s;
}

Eigen::Vector3d parabola(double t) { return kC0 + kV0 * t + 0.5 * kG * t * t; }

TEST(Gravity, ForceSetIsNotEmptyButHasNoTorque) {
  const RigidBodyModel m = gravity_body();
  EXPECT_FALSE(m.forces.empty());
  EXPECT_FALSE(m.forces.has_torque());
}

TEST(Gravity, ExactParabolaToRoundOff) {
  const RigidBodyModel m = gravity_body();
  const BodyState s0 = initial(m);
  const FreeRotationExact free_rotation(m.inertia, s0.q, s0.L);
  for (Method method : {Method::splitting, Method::splitting4, Method::rk4, Method::exact, Method::implicit_midpoint}) {
    for (double h : {0.1, 1e-2}) {
      const BodyState s = testing::run_steps(method, m, s0, h, std::lround(kT / h));
      EXPECT_LT((s.c - parabola(kT)).norm(), 1e-12 * (1 + parabola(kT).norm()) * (kT / h))
          << testing::name_of(method) << " dt=" << h;
      EXPECT_LT((s.P - m.mass * (kV0 + kG * kT)).norm(), 1e-12 * m.mass * (kV0 + kG * kT).norm() * (kT / h))
          << testing::name_of(method) << " dt=" << h;
      // No torque: the geometric methods leave L untouched. rk4 integrates
      // Π = Rᵀ L (body_frame.hpp), so world L moves by its truncation error.
      if (method == Method::rk4) {
        EXPECT_LT((s.L - s0.L).norm(), (h > 0.05 ? 1e-4 : 1e-8) * s0.L.norm()) << "rk4 dt=" << h;
      } else {
        EXPECT_EQ(s.L, s0.L) << testing::name_of(method);
      }
      if (method == Method::exact) {  // and the rotation is still the closed form
        EXPECT_LT(rotation_angle_between(s.q, free_rotation.orientation(kT)), 1e-12);
      }
    }
  }
}

TEST(Gravity, EulerIsFirstOrderWithTheKnownError) {
  const RigidBodyModel m = gravity_body();
  const BodyState s0 = initial(m);
  for (double h : {0.1, 0.05, 0.025}) {
    const long n = std::lround(kT / h);
    const BodyState e = testing::run_steps(Method::euler, m, s0, h, n);
    const BodyState si = testing::run_steps(Method::semi_implicit_euler, m, s0, h, n);
    const Eigen::Vector3d lag = 0.5 * kG * kT * h;  // exact error of each scheme
    EXPECT_LT((e.c - (parabola(kT) - lag)).norm(), 1e-12) << "euler dt=" << h;
    EXPECT_LT((si.c - (parabola(kT) + lag)).norm(), 1e-12) << "semi_implicit_euler dt=" << h;
    // The velocity is exact for both (P' = M g is constant).
    EXPECT_LT((e.P - m.mass * (kV0 + kG * kT)).norm(), 1e-12);
  }
}

TEST(Gravity, PropagatorSamplesTheParabola) {
  const RigidBodyModel m = gravity_body();
  const BodyState s0 = initial(m);
  for (Method method : {Method::splitting, Method::rk4, Method::exact, Method::rk45}) {
    StepConfig cfg;
    cfg.method = method;
    cfg.dt = 0.01;
    Propagator p(m, s0, cfg);
    for (int k = 1; k <= 60; ++k) {
      const double t = k / 30.0;
      const BodyState& s = p.advance_to(t);
      const double tol = method == Method::rk45 ? 1e-8 : 1e-11;
      EXPECT_LT((s.c - parabola(t)).norm(), tol) << testing::name_of(method) << " t=" << t;
    }
  }
}

}  // namespace
}  // namespace tumble
