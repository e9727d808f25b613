// The seed's ODE as one pure function, and the quantities derived from a state.
#pragma once

#include <cmath>

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

/// q' = ½ ω_world ⊗ q for world L, ω_world = q I⁻¹ (q̄ L), evaluated in the
/// body frame as ½ q ⊗ (0, ω_b), ω_b = I⁻¹ Π, Π = q̄ L — the product the seed's
/// Q(q) forms, which is right exactly for this body-frame ω (docs/model.md, erratum 1).
/// One rotation fewer on the latency chain of an RK stage.
///
/// RK stages are not unit quaternions, and Eigen's rotation q v = v + 2w(u×v) +
/// 2u×(u×v) is q v q̄ + (1 - |q|²) v there. Expanding ½ (0, q ω_b) ⊗ q with it
/// gives ½ (-u·ω_b, w ω_b + (2|q|² - 1) u × ω_b): the same vector field on all
/// of R⁴, not only on |q| = 1 (without the 2|q|² - 1 factor the RK4 result
/// moves by O(h⁵) per step, not by round-off). Spelt out in scalars, operation
/// for operation as the Eigen expression in tests/core/fast_path_test.cpp
/// (2·(a×b) is formed as (2a)×b etc., exact doublings, one level shorter).
/// The scalar overload is for hot loops (rk4_free): always inlined, no packing.
struct QuatRate {
  double x, y, z, w;  // Eigen's coefficient order
};
[[gnu::always_inline]] inline QuatRate quaternion_rate(const Eigen::Vector3d& inv_inertia, double x, double y,
                                                      double z, double w, const Eigen::Vector3d& L) {
  // Π = q̄ L (Eigen: L + w·2(v×L) + v×2(v×L), v = -u); the doublings move onto w
  // and v, which are ready first.
  const double vx = -x, vy = -y, vz = -z, w2 = w + w, vx2 = vx + vx, vy2 = vy + vy, vz2 = vz + vz;
  const double ux = vy * L.z() - vz * L.y(), uy = vz * L.x() - vx * L.z(), uz = vx * L.y() - vy * L.x();
  const double pix = L.x() + w2 * ux + (vy2 * uz - vz2 * uy), piy = L.y() + w2 * uy + (vz2 * ux - vx2 * uz),
               piz = L.z() + w2 * uz + (vx2 * uy - vy2 * ux);
  // ½ω_b: 0.5·I⁻¹ is exact and off the chain.
  const double ox = (0.5 * inv_inertia.x()) * pix, oy = (0.5 * inv_inertia.y()) * piy,
               oz = (0.5 * inv_inertia.z()) * piz;
  // g u with g = 2|q|² - 1 (= u on the unit sphere), also off the chain.
  const double g = 2 * ((x * x + z * z) + (y * y + w * w)) - 1, gx = g * x, gy = g * y, gz = g * z;
  return {w * ox + (gy * oz - gz * oy), w * oy + (gz * ox - gx * oz), w * oz + (gx * oy - gy * ox),
          -(x * ox + y * oy + z * oz)};
}
inline Eigen::Vector4d quaternion_rate(const RigidBodyModel& m, const Eigen::Quaterniond& q,
                                       const Eigen::Vector3d& L) {
  const QuatRate r = quaternion_rate(m.inv_inertia, q.x(), q.y(), q.z(), q.w(), L);
  return {r.x, r.y, r.z, r.w};
}

/// Pure: depends only on its arguments. `t` (s) is unused by the current force
/// terms but is part of the signature so time-dependent forcing fits.
Derivative derivative(const RigidBodyModel& m, const BodyState& s, double t);

/// Sum of the body's force terms (forces.hpp), in list order.
Wrench wrench(const RigidBodyModel& m, const BodyState& s, double t);

inline Eigen::Vector3d velocity(const RigidBodyModel& m, const BodyState& s) { return s.P / m.mass; }
/// Π = Rᵀ L: angular momentum in the principal frame, kg·m²/s.
inline Eigen::Vector3d momentum_body(const BodyState& s) { return rotate_inverse(s.q, s.L); }  // q̄ L, Eigen's bits
/// ω in the principal frame, rad/s.
inline Eigen::Vector3d omega_principal(const RigidBodyModel& m, const BodyState& s) {
  return m.inv_inertia.cwiseProduct(momentum_body(s));
}
/// ω_world = R J0⁻¹ Rᵀ L, rad/s.
inline Eigen::Vector3d omega_world(const RigidBodyModel& m, const BodyState& s) {
  return rotate(s.q, omega_principal(m, s));
}
/// ω in the cloud's own axes (the scene's `omega_body`), rad/s.
inline Eigen::Vector3d omega_body(const RigidBodyModel& m, const BodyState& s) {
  return m.cloud_from_principal * omega_principal(m, s);
}

/// Angle between each principal axis (I1 ≤ I2 ≤ I3) and L, rad in [0, π];
/// atan2 keeps it accurate near 0 and π. Zero when L = 0.
inline Eigen::Vector3d principal_axis_angles_to_L(const BodyState& s) {
  const Eigen::Vector3d p = momentum_body(s);
  Eigen::Vector3d out;
  for (int i = 0; i < 3; ++i) {
    const double along = p[i], across = std::hypot(p[(i + 1) % 3], p[(i + 2) % 3]);
    out[i] = std::atan2(across, along);
  }
  return out;
}

/// Rotational kinetic energy ½ Π·I⁻¹Π of the body-frame momentum Π (kg·m²/s), J.
inline double rotational_energy(const RigidBodyModel& m, const Eigen::Vector3d& pi) {
  return 0.5 * pi.dot(m.inv_inertia.cwiseProduct(pi));
}

/// Kinetic energy ½|P|²/M + ½ Π·I⁻¹Π, J.
double kinetic_energy(const RigidBodyModel& m, const BodyState& s);
/// Sum of the terms' potentials (uniform gravity: -M g·c), J.
double potential_energy(const RigidBodyModel& m, const BodyState& s);
inline double total_energy(const RigidBodyModel& m, const BodyState& s) {
  return kinetic_energy(m, s) + potential_energy(m, s);
}

/// Where energy goes (W): `driving` is the power of the terms whose `work` is
/// Work::driving (point forces, constant torques); `scale` adds |power| of the
/// conservative ones, the size against which an energy balance is judged.
/// Dissipative terms only remove energy, so they are in neither.
struct EnergyFlow {
  double driving = 0, scale = 0;
};
EnergyFlow energy_flow(const RigidBodyModel& m, const BodyState& s);

/// Diagnostics (seed §3, §5): a = f/M and α = J⁻¹(τ - ω × Jω), world frame.
Eigen::Vector3d linear_acceleration(const RigidBodyModel& m, const BodyState& s, double t);
Eigen::Vector3d angular_acceleration(const RigidBodyModel& m, const BodyState& s, double t);

/// Exact flow over `h` (s) of the force terms alone, c and q frozen (the "kick"
/// of a Strang splitting): the terms' KickParts summed, P' = F - aP and
/// Π' = τ_b - a_i Π, solved in closed form.
BodyState kick(const RigidBodyModel& m, const BodyState& s, double t, double h);

/// Largest decay rate of the momenta under the terms' damping, 1/s:
/// max(k_lin/M, k_ang max I⁻¹ᵢ).
double damping_rate(const RigidBodyModel& m);

}  // namespace tumble
