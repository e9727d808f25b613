#include "core/dynamics.hpp"

#include <cmath>

namespace tumble {

namespace {

// Forces that do not depend on the momenta: gravity, point forces, constant torques.
Wrench position_wrench(const RigidBodyModel& m, const BodyState& s) {
  Wrench w;
  const auto& f = m.forces;
  if (f.has_gravity) w.force += m.mass * f.gravity;
  if (!f.point_forces.empty()) {
    const Eigen::Quaterniond world_from_cloud = cloud_orientation(m, s);
    for (const PointForce& pf : f.point_forces) {
      const Eigen::Vector3d F = pf.frame == Frame::world ? pf.force : world_from_cloud * pf.force;
      const Eigen::Vector3d r = world_from_cloud * (pf.point - m.com_cloud);
      w.force += F;
      w.torque += r.cross(F);
    }
  }
  w.torque += f.torque_world;
  if (!f.torque_body.isZero(0)) w.torque += cloud_orientation(m, s) * f.torque_body;
  return w;
}

// (1 - e^{-x}) / x, accurate near 0: the factor of the exact linear-ODE flow.
double phi1(double x) { return x == 0.0 ? 1.0 : -std::expm1(-x) / x; }

}  // namespace

Wrench wrench(const RigidBodyModel& m, const BodyState& s, double /*t*/) {
  Wrench w = position_wrench(m, s);
  if (m.forces.linear_damping != 0) w.force -= m.forces.linear_damping * velocity(m, s);
  if (m.forces.angular_damping != 0) w.torque -= m.forces.angular_damping * omega_world(m, s);
  return w;
}

Derivative derivative(const RigidBodyModel& m, const BodyState& s, double t) {
  Derivative d;
  d.dc = s.P / m.mass;
  // q' = ½ ω_world ⊗ q (erratum 1). The seed's Q(q) computes ½ q ⊗ ω, which is
  // right only for a body-frame ω.
  d.dq = quaternion_rate(m, s.q, s.L);
  if (m.forces.empty()) {
    d.dP.setZero();
    d.dL.setZero();
  } else {
    const Wrench f = wrench(m, s, t);
    d.dP = f.force;
    d.dL = f.torque;
  }
  return d;
}

double kinetic_energy(const RigidBodyModel& m, const BodyState& s) {
  const Eigen::Vector3d pi = momentum_body(s);
  return 0.5 * s.P.squaredNorm() / m.mass + 0.5 * pi.dot(m.inv_inertia.cwiseProduct(pi));
}

double potential_energy(const RigidBodyModel& m, const BodyState& s) {
  return m.forces.has_gravity ? -m.mass * m.forces.gravity.dot(s.c) : 0.0;
}

EnergyFlow energy_flow(const RigidBodyModel& m, const BodyState& s) {
  EnergyFlow e;
  const auto& f = m.forces;
  const Eigen::Vector3d v = velocity(m, s);
  const double gravity = f.has_gravity ? m.mass * f.gravity.dot(v) : 0.0;
  if (f.has_torque() || !f.point_forces.empty()) {
    Wrench w = position_wrench(m, s);
    if (f.has_gravity) w.force -= m.mass * f.gravity;
    e.driving = w.force.dot(v) + w.torque.dot(omega_world(m, s));
  }
  e.scale = std::abs(e.driving) + std::abs(gravity);
  return e;
}

Eigen::Vector3d linear_acceleration(const RigidBodyModel& m, const BodyState& s, double t) {
  return wrench(m, s, t).force / m.mass;
}

Eigen::Vector3d angular_acceleration(const RigidBodyModel& m, const BodyState& s, double t) {
  // Seed §5 (erratum 3): α = J⁻¹(τ - ω × Jω), evaluated in the principal frame.
  const Eigen::Vector3d tau_b = s.q.conjugate() * wrench(m, s, t).torque;
  const Eigen::Vector3d w = omega_principal(m, s);
  const Eigen::Vector3d alpha_b = m.inv_inertia.cwiseProduct(tau_b - w.cross(m.inertia.cwiseProduct(w)));
  return s.q * alpha_b;
}

BodyState kick(const RigidBodyModel& m, const BodyState& s, double /*t*/, double h) {
  BodyState out = s;
  const Wrench w = position_wrench(m, s);
  // P' = F - a P with a = k/M: P(h) = P + h (F - a P) φ1(a h).
  const double a = m.forces.linear_damping / m.mass;
  out.P = s.P + h * phi1(a * h) * (w.force - a * s.P);
  if (w.torque.isZero(0) && m.forces.angular_damping == 0) return out;
  // Π' = τ_b - k I⁻¹ Π, componentwise in the principal frame (q frozen).
  const Eigen::Vector3d tau_b = s.q.conjugate() * w.torque;
  Eigen::Vector3d pi = momentum_body(s);
  for (int i = 0; i < 3; ++i) {
    const double ai = m.forces.angular_damping * m.inv_inertia[i];
    pi[i] += h * phi1(ai * h) * (tau_b[i] - ai * pi[i]);
  }
  out.L = s.q * pi;
  return out;
}

}  // namespace tumble
