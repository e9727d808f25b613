// Euler's coordinates for the rotation: the RK-type methods integrate
// (c, q, P, Π) with Π = Rᵀ L (principal frame), Π' = Π × ω_body + Rᵀ τ and
// q' = ½ q ⊗ (0, ω_body), ω_body = I⁻¹ Π. The ODE is the seed's; only the
// coordinates differ. On the README's reference problem (dt = 1 ms, 10 s) RK4
// in these coordinates errs 1.3e-9 rad against 1.6e-3 rad in the seed's
// (q, L_world): the seed's form lets the RK error move |Π| and 2T off their
// level sets independently, and near the separatrix that moves the flip times
// (issue #10 §1; Boost.odeint's body-frame RK4 measured 8.4e-10).
//
// These are the plain Eigen forms (the reference the tuned kernels in
// body_frame_tuned.hpp must reproduce bit for bit).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/body.hpp"
#include "core/dynamics.hpp"

namespace tumble {

/// A state in Euler's coordinates. q need not be a unit quaternion inside an RK
/// stage; everything that rotates a vector with it normalises a copy first.
struct BodyCoords {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();      ///< centre of mass, world, m
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();  ///< world ← principal
  Eigen::Vector3d P = Eigen::Vector3d::Zero();      ///< linear momentum, world, kg·m/s
  Eigen::Vector3d pi = Eigen::Vector3d::Zero();     ///< Π = Rᵀ L, principal frame, kg·m²/s
};

/// Π = q̄ L (q unit).
BodyCoords to_body_coords(const BodyState& s);
/// L = q Π after normalising q (the state the rest of tumble sees).
BodyState from_body_coords(const BodyCoords& x);

/// d/dt of (c, q, P, Π); dq as Eigen's coefficients (x, y, z, w).
struct BodyRate {
  Eigen::Vector3d dc, dP, dpi;
  Eigen::Vector4d dq;
};

/// The seed's ODE in Euler's coordinates: c' = P/M, q' = ½ q ⊗ (0, I⁻¹Π),
/// P' = F, Π' = Π × I⁻¹Π + q̄ τ (F, τ from `wrench` at the state, world frame).
BodyRate body_rate(const RigidBodyModel& m, const BodyCoords& x, double t);

/// x + h·d, componentwise (no normalisation): the building block of RK stages.
BodyCoords add_scaled(const BodyCoords& x, double h, const BodyRate& d);

/// Kutta's classical RK4 (HNW I, Table 1.2) in Euler's coordinates, plain form:
/// four stages of body_rate, x + h(k1 + 2k2 + 2k3 + k4)/6 summed as
/// ((x + (h/6)k1) + (h/3)k2) + (h/3)k3) + (h/6)k4, then q normalised.
BodyState rk4_body_reference(const RigidBodyModel& m, const BodyState& s, double t, double h);

/// The method `rk4`: rk4_body_reference, through the tuned kernel for
/// torque-free bodies (same bits; see body_frame_tuned.hpp).
BodyState rk4_body_step(const RigidBodyModel& m, const BodyState& s, double t, double h);

}  // namespace tumble
