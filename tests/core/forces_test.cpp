// Declared forces and torques, checked against their definitions and the
// closed-form solutions of the damped motions.
#include <gtest/gtest.h>

#include <cmath>

#include "core/dynamics.hpp"
#include "core/integrator.hpp"
#include "core/mass_properties.hpp"
#include "core/propagator.hpp"
#include "core/methods/rotation_steps.hpp"
#include "test_helpers.hpp"

namespace tumble {
namespace {

// An asymmetric cloud whose centre of mass is off the origin and whose principal
// axes are not the cloud axes, so frame conversions are exercised.
ParticleCloud skewed_cloud() {
  return {{{1.0, 0.2, 0.1}, 1.0}, {{-0.8, 0.3, -0.2}, 2.0}, {{0.1, 1.1, 0.4}, 0.5},
          {{0.2, -0.9, 0.7}, 1.5}, {{0.4, 0.1, -1.2}, 0.7}, {{2.0, 2.0, 2.0}, 0.3}};
}

struct BodySetup {
  RigidBodyModel m;
  BodyState s;
  Eigen::Quaterniond orientation;  // world ← cloud
};

BodySetup make(const ForceSet& f) {
  BodySetup u;
  u.m = make_model("skewed", compute_mass_properties(skewed_cloud(), "skewed"), f);
  InitialConditions ic;
  ic.position = {1, 2, 3};
  ic.orientation = Eigen::Quaterniond(0.9, -0.2, 0.3, 0.25).normalized();
  ic.velocity = {0.5, -0.1, 0.2};
  ic.omega = {0.4, -1.3, 2.1};
  u.s = make_state(u.m, ic);
  u.orientation = ic.orientation;
  return u;
}

TEST(Forces, PointForceYieldsTorqueRCrossF) {
  const Eigen::Vector3d F(0.3, -2.0, 1.1), point(0.7, -0.4, 1.9);
  for (Frame frame : {Frame::world, Frame::body}) {
    ForceSet f;
    f.terms.push_back(PointForce{F, point, frame});
    const BodySetup u = make(f);
    EXPECT_TRUE(u.m.forces.has_torque());
    const Eigen::Vector3d F_world = frame == Frame::world ? F : u.orientation * F;
    const Eigen::Vector3d r = u.orientation * (point - u.m.com_cloud);  // from c to the point, world
    const Derivative d = derivative(u.m, u.s, 0.0);
    EXPECT_LT((d.dP - F_world).norm(), 1e-14);
    EXPECT_LT((d.dL - r.cross(F_world)).norm(), 1e-14);
    // A force through the centre of mass has no torque.
    ForceSet g;
    g.terms.push_back(PointForce{F, u.m.com_cloud, frame});
    const BodySetup v = make(g);
    EXPECT_LT(derivative(v.m, v.s, 0.0).dL.norm(), 1e-14);
  }
}

TEST(Forces, ConstantTorqueInWorldAndBodyFrame) {
  const Eigen::Vector3d tau(0.2, -0.7, 1.3);
  ForceSet fw;
  fw.terms.push_back(ConstantTorque{tau, Frame::world});
  const BodySetup w = make(fw);
  EXPECT_LT((derivative(w.m, w.s, 0.0).dL - tau).norm(), 1e-15);
  ForceSet fb;
  fb.terms.push_back(ConstantTorque{tau, Frame::body});  // in the cloud's own axes
  const BodySetup b = make(fb);
  EXPECT_LT((derivative(b.m, b.s, 0.0).dL - b.orientation * tau).norm(), 1e-14);
  EXPECT_LT(derivative(b.m, b.s, 0.0).dP.norm(), 1e-15);
  // A torque in the body frame follows the body: after the body turns, so does dL.
  const BodyState later = step(Method::rk4, b.m, b.s, 0.0, 0.3);
  EXPECT_LT((derivative(b.m, later, 0.3).dL - cloud_orientation(b.m, later) * tau).norm(), 1e-14);
}

TEST(Forces, LinearDampingDecaysMomentumExponentially) {
  ForceSet f;
  const double k = 0.8;  // N·s/m
  f.terms.push_back(LinearDamping{k});
  const BodySetup u = make(f);
  const double M = u.m.mass;
  // One kick of h is the exact flow P(h) = P0 e^{-kh/M}.
  for (double h : {1e-3, 0.1, 1.0, 10.0}) {
    const BodyState s = kick(u.m, u.s, 0.0, h);
    EXPECT_LT((s.P - u.s.P * std::exp(-k * h / M)).norm(), 1e-15 * u.s.P.norm()) << "h=" << h;
  }
  // Strang methods compose exact kicks: P(T) is exact for any dt.
  for (Method method : {Method::splitting, Method::implicit_midpoint, Method::exact}) {
    const BodyState s = testing::run_steps(method, u.m, u.s, 0.25, 8);
    EXPECT_LT((s.P - u.s.P * std::exp(-k * 2.0 / M)).norm(), 1e-14 * u.s.P.norm()) << testing::name_of(method);
  }
  // The derivative is the damping force -k v.
  EXPECT_LT((derivative(u.m, u.s, 0.0).dP + k * u.s.P / M).norm(), 1e-15);
}

TEST(Forces, AngularDampingOfASphericalBodyDecaysOmegaExponentially) {
  // Six equal masses on the axes: J = 4 m a² I (spherical).
  const double mass = 0.5, a = 0.6;
  ParticleCloud cloud;
  for (int i = 0; i < 3; ++i)
    for (double sgn : {1.0, -1.0}) cloud.push_back({sgn * a * Eigen::Vector3d::Unit(i), mass});
  ForceSet f;
  const double k = 0.3;  // N·m·s
  f.terms.push_back(AngularDamping{k});
  const RigidBodyModel m = make_model("ball", compute_mass_properties(cloud, "ball"), f);
  const double I = 4 * mass * a * a;
  EXPECT_LT((m.inertia - Eigen::Vector3d::Constant(I)).norm(), 1e-15);
  InitialConditions ic;
  ic.orientation = Eigen::Quaterniond(0.6, 0.3, -0.2, 0.7).normalized();
  ic.omega = {1.5, -2.0, 0.7};
  const BodyState s0 = make_state(m, ic);
  const Eigen::Vector3d w0 = omega_world(m, s0);
  for (double h : {0.1, 1.0, 5.0}) {
    const BodyState s = kick(m, s0, 0.0, h);
    EXPECT_LT((omega_world(m, s) - w0 * std::exp(-k * h / I)).norm(), 1e-14) << "h=" << h;
  }
  for (Method method : {Method::splitting, Method::implicit_midpoint, Method::exact}) {
    const BodyState s = testing::run_steps(method, m, s0, 0.05, 40);
    EXPECT_LT((omega_world(m, s) - w0 * std::exp(-k * 2.0 / I)).norm(), 1e-13)
        << testing::name_of(method);
  }
  // RK4 is not exact here; it converges to the same exponential at 4th order.
  const Eigen::Vector3d w_exact = w0 * std::exp(-k * 2.0 / I);
  const double e1 = (omega_world(m, testing::run_steps(Method::rk4, m, s0, 0.02, 100)) - w_exact).norm();
  const double e2 = (omega_world(m, testing::run_steps(Method::rk4, m, s0, 0.01, 200)) - w_exact).norm();
  EXPECT_NEAR(std::log2(e1 / e2), 4.0, 0.3) << e1 << " " << e2;
}

TEST(Forces, NoForcesIsTheTorqueFreePathAndLeavesLBitwiseUnchanged) {
  const BodySetup u = make(ForceSet{});
  EXPECT_TRUE(u.m.forces.empty());
  EXPECT_FALSE(u.m.forces.has_torque());
  const Derivative d = derivative(u.m, u.s, 0.0);
  EXPECT_EQ(d.dP, Eigen::Vector3d::Zero());
  EXPECT_EQ(d.dL, Eigen::Vector3d::Zero());
  for (Method method : {Method::splitting, Method::splitting4, Method::implicit_midpoint, Method::exact,
                        Method::semi_implicit_euler}) {
    const BodyState s = testing::run_steps(method, u.m, u.s, 0.01, 1000);
    EXPECT_EQ(s.L, u.s.L) << testing::name_of(method);  // bit for bit
    EXPECT_EQ(s.P, u.s.P) << testing::name_of(method);
  }
}

// Seed §5: α = J⁻¹(τ − ω × Jω). For a torque-free body it must match the time
// derivative of ω_world along the exact motion (central difference).
TEST(Forces, AngularAccelerationIsTheDerivativeOfOmega) {
  const BodySetup u = make(ForceSet{});
  const double h = 1e-5;
  const BodyState sp = step(Method::exact, u.m, u.s, 0.0, h);
  const BodyState sm = step(Method::exact, u.m, u.s, 0.0, -h);
  const Eigen::Vector3d fd = (omega_world(u.m, sp) - omega_world(u.m, sm)) / (2 * h);
  const Eigen::Vector3d alpha = angular_acceleration(u.m, u.s, 0.0);
  EXPECT_LT((alpha - fd).norm(), 1e-7 * (1 + alpha.norm()));
  EXPECT_GT(alpha.norm(), 0.1);  // the asymmetric body does accelerate
}

}  // namespace
}  // namespace tumble

namespace tumble {
namespace {

// Energy conservation, the energy balance's power and the
// potential are derived in core from the terms' declared `work` and `potential`.
TEST(ForceTerms, EnergyConservationIsDecidedFromTheTerms) {
  ForceSet f;
  EXPECT_TRUE(f.conserves_energy());
  f.terms.push_back(UniformGravity{Eigen::Vector3d(0, 0, -9.81)});
  EXPECT_TRUE(f.conserves_energy());
  EXPECT_FALSE(f.has_torque());
  ForceSet damped = f;
  damped.terms.push_back(LinearDamping{0.5});
  EXPECT_FALSE(damped.conserves_energy());
  EXPECT_FALSE(damped.has_torque());
  ForceSet driven = f;
  driven.terms.push_back(ConstantTorque{Eigen::Vector3d(0, 0, 1), Frame::world});
  EXPECT_FALSE(driven.conserves_energy());
  EXPECT_TRUE(driven.has_torque());
  ForceSet spun;
  spun.terms.push_back(AngularDamping{0.1});
  EXPECT_TRUE(spun.has_torque());
}

TEST(ForceTerms, PotentialPowerAndKickOfEachTerm) {
  const Eigen::Vector3d g(0.3, -0.2, -9.81), tau(0.2, -0.7, 1.3);
  ForceSet f;
  f.terms.push_back(UniformGravity{g});
  f.terms.push_back(ConstantTorque{tau, Frame::world});
  f.terms.push_back(LinearDamping{0.4});
  const BodySetup u = make(f);
  const double M = u.m.mass;
  // Gravity's potential is -M g·c; the others have none.
  EXPECT_DOUBLE_EQ(potential_energy(u.m, u.s), -M * g.dot(u.s.c));
  // Driving power is the torque's τ·ω alone; the scale adds |M g·v|; damping is in neither.
  const EnergyFlow e = energy_flow(u.m, u.s);
  EXPECT_NEAR(e.driving, tau.dot(omega_world(u.m, u.s)), 1e-14);
  EXPECT_NEAR(e.scale, std::abs(e.driving) + std::abs(M * g.dot(velocity(u.m, u.s))), 1e-14);
  // The kick is the exact flow of P' = M g - (k/M) P: P(h) = P∞ + (P0 - P∞) e^{-kh/M}, P∞ = M² g / k.
  const double k = 0.4, h = 0.7;
  const Eigen::Vector3d p_inf = M * M * g / k;
  const BodyState s = kick(u.m, u.s, 0.0, h);
  EXPECT_LT((s.P - (p_inf + (u.s.P - p_inf) * std::exp(-k * h / M))).norm(), 1e-13 * p_inf.norm());
  // ... and L gains τ h exactly (no angular damping): c and q stay frozen.
  EXPECT_LT((s.L - (u.s.L + h * tau)).norm(), 1e-14);
  EXPECT_EQ(s.c, u.s.c);
  EXPECT_EQ(s.q.coeffs(), u.s.q.coeffs());
  EXPECT_DOUBLE_EQ(damping_rate(u.m), k / M);
}

}  // namespace
}  // namespace tumble
