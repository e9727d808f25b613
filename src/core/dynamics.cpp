#include "core/dynamics.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

namespace tumble {

namespace {

// (1 - e^{-x}) / x, accurate near 0: the factor of the exact linear-ODE flow.
double phi1(double x) { return x == 0.0 ? 1.0 : -std::expm1(-x) / x; }

}  // namespace

Wrench wrench(const RigidBodyModel& m, const BodyState& s, double /*t*/) {
  Wrench w;
  for (const ForceTerm& term : m.forces.terms) std::visit([&](const auto& f) { f.add_wrench(m, s, w); }, term);
  return w;
}

namespace {
KickPart kick_part(const RigidBodyModel& m, const BodyState& s) {
  KickPart k;
  for (const ForceTerm& term : m.forces.terms) std::visit([&](const auto& f) { f.add_kick(m, s, k); }, term);
  return k;
}
}  // namespace

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
  return 0.5 * s.P.squaredNorm() / m.mass + rotational_energy(m, pi);
}

double potential_energy(const RigidBodyModel& m, const BodyState& s) {
  double u = 0;
  for (const ForceTerm& term : m.forces.terms) u += std::visit([&](const auto& f) { return f.potential(m, s); }, term);
  return u;
}

EnergyFlow energy_flow(const RigidBodyModel& m, const BodyState& s) {
  EnergyFlow e;
  if (m.forces.empty()) return e;
  const Eigen::Vector3d v = velocity(m, s), w = omega_world(m, s);
  double conservative = 0;
  for (const ForceTerm& term : m.forces.terms)
    std::visit(
        [&](const auto& f) {
          if (f.work == Work::dissipative) return;
          Wrench x;
          f.add_wrench(m, s, x);
          const double power = x.force.dot(v) + x.torque.dot(w);
          if (f.work == Work::driving) e.driving += power;
          else conservative += std::abs(power);
        },
        term);
  e.scale = std::abs(e.driving) + conservative;
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
  const KickPart k = kick_part(m, s);
  const Wrench& w = k.constant;
  // P' = F - a P with a = k/M: P(h) = P + h (F - a P) φ1(a h).
  const double a = k.linear_damping / m.mass;
  out.P = s.P + h * phi1(a * h) * (w.force - a * s.P);
  if (w.torque.isZero(0) && k.angular_damping == 0) return out;
  // Π' = τ_b - k I⁻¹ Π, componentwise in the principal frame (q frozen).
  const Eigen::Vector3d tau_b = s.q.conjugate() * w.torque;
  Eigen::Vector3d pi = momentum_body(s);
  for (int i = 0; i < 3; ++i) {
    const double ai = k.angular_damping * m.inv_inertia[i];
    pi[i] += h * phi1(ai * h) * (tau_b[i] - ai * pi[i]);
  }
  out.L = s.q * pi;
  return out;
}

double damping_rate(const RigidBodyModel& m) {
  const KickPart k = kick_part(m, BodyState{});
  return std::max(k.angular_damping * m.inv_inertia.maxCoeff(), k.linear_damping / m.mass);
}

}  // namespace tumble
