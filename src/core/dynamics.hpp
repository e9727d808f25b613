// The seed's ODE as one pure function, and the quantities derived from a state.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/body.hpp"
#include "core/quaternion.hpp"

namespace tumble {

/// dx/dt = (v, ½ ω_world ⊗ q, f, τ) (seed §1 with erratum 1: ω is world-frame,
/// so it multiplies q from the left). Quaternion derivative as (x, y, z, w).
struct Derivative {
  Eigen::Vector3d dc, dP, dL;
  Eigen::Vector4d dq;
};

/// Total force (N) and torque about c (N·m), world frame.
struct Wrench {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
};

/// q' = ½ ω_world ⊗ q for world L, where ω_world = q I⁻¹ (q̄ L); q need not be
/// unit (RK stages). Spelt out in scalars for speed, operation for operation as
/// Eigen evaluates `q * v` (v + w·2(u×v) + u×2(u×v)) and its SSE2 quaternion
/// product, so the bits match the Eigen expression (tests/core/rk_fast_path_test).
inline Eigen::Vector4d quaternion_rate(const RigidBodyModel& m, const Eigen::Quaterniond& q,
                                       const Eigen::Vector3d& L) {
  const double w = q.w(), x = q.x(), y = q.y(), z = q.z();
  // Π = q̄ L (vector part -u).
  double ux = -y * L.z() - -z * L.y(), uy = -z * L.x() - -x * L.z(), uz = -x * L.y() - -y * L.x();
  ux += ux, uy += uy, uz += uz;
  const double pix = L.x() + w * ux + (-y * uz - -z * uy), piy = L.y() + w * uy + (-z * ux - -x * uz),
               piz = L.z() + w * uz + (-x * uy - -y * ux);
  const double bx = m.inv_inertia.x() * pix, by = m.inv_inertia.y() * piy, bz = m.inv_inertia.z() * piz;
  // ω = q ω_b.
  double vx = y * bz - z * by, vy = z * bx - x * bz, vz = x * by - y * bx;
  vx += vx, vy += vy, vz += vz;
  const double ox = bx + w * vx + (y * vz - z * vy), oy = by + w * vy + (z * vx - x * vz),
               oz = bz + w * vz + (x * vy - y * vx);
  // (0, ω) ⊗ q in Eigen's SSE2 grouping; its terms in the zero w are exact zeros.
  return 0.5 * Eigen::Vector4d(oy * z - (oz * y - ox * w), oy * w + (oz * x - ox * z),
                               -(oy * x) + (oz * w + ox * y), -(oy * y) - (oz * z + ox * x));
}

/// Pure: depends only on its arguments. `t` (s) is unused by the current force
/// terms but is part of the signature so time-dependent forcing fits.
Derivative derivative(const RigidBodyModel& m, const BodyState& s, double t);

Wrench wrench(const RigidBodyModel& m, const BodyState& s, double t);

inline Eigen::Vector3d velocity(const RigidBodyModel& m, const BodyState& s) { return s.P / m.mass; }
/// Π = Rᵀ L: angular momentum in the principal frame, kg·m²/s.
inline Eigen::Vector3d momentum_body(const BodyState& s) { return s.q.conjugate() * s.L; }
/// ω in the principal frame, rad/s.
inline Eigen::Vector3d omega_principal(const RigidBodyModel& m, const BodyState& s) {
  return m.inv_inertia.cwiseProduct(momentum_body(s));
}
/// ω_world = R J0⁻¹ Rᵀ L, rad/s.
inline Eigen::Vector3d omega_world(const RigidBodyModel& m, const BodyState& s) {
  return s.q * omega_principal(m, s);
}
/// ω in the cloud's own axes (the scene's `omega_body`), rad/s.
inline Eigen::Vector3d omega_body(const RigidBodyModel& m, const BodyState& s) {
  return m.cloud_from_principal * omega_principal(m, s);
}

/// Kinetic energy ½|P|²/M + ½ Π·I⁻¹Π, J.
double kinetic_energy(const RigidBodyModel& m, const BodyState& s);
/// Potential of declared conservative fields (uniform gravity: -M g·c), J.
double potential_energy(const RigidBodyModel& m, const BodyState& s);
inline double total_energy(const RigidBodyModel& m, const BodyState& s) {
  return kinetic_energy(m, s) + potential_energy(m, s);
}

/// Diagnostics (seed §3, §5): a = f/M and α = J⁻¹(τ - ω × Jω), world frame.
Eigen::Vector3d linear_acceleration(const RigidBodyModel& m, const BodyState& s, double t);
Eigen::Vector3d angular_acceleration(const RigidBodyModel& m, const BodyState& s, double t);

/// Exact flow over `h` (s) of the force field alone, c and q frozen (the "kick"
/// of a Strang splitting). Forces are constant or linear in the momenta
/// (damping), so P' = F - aP and Π' = τ_b - a_i Π solve in closed form.
BodyState kick(const RigidBodyModel& m, const BodyState& s, double t, double h);

}  // namespace tumble
