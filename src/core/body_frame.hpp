// Euler's coordinates for the rotation: the RK-type methods integrate
// (c, q, P, Π) with Π = Rᵀ L (principal frame), Π' = Π × ω_body + Rᵀ τ and
// q' = ½ q ⊗ (0, ω_body), ω_body = I⁻¹ Π. The ODE is the seed's; only the
// coordinates differ. On the reference problem (docs/methods.md) (dt = 1 ms, 10 s) RK4
// in these coordinates errs 1.3e-9 rad against 1.6e-3 rad in the seed's
// (q, L_world): the seed's form lets the RK error move |Π| and 2T off their
// level sets independently, and near the separatrix that moves the flip times
// (Boost.odeint's body-frame RK4 measured 8.4e-10).
//
// These are the plain Eigen forms (the reference the tuned kernels in
// body_frame_tuned.hpp must reproduce bit for bit).
#pragma once

#include <cmath>

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
  /// Round-off lost by the last step's sum Π + ΔΠ, kg·m²/s (compensated
  /// summation, Kahan 1965; Hairer, Lubich & Wanner, Geometric Numerical
  /// Integration, §VIII.5): the next step subtracts it from its ΔΠ. Zero from
  /// to_body_coords. Π alone needs it: its round-off moves the body across
  /// energy levels, which near the separatrix moves the flips; q's, c's and P's
  /// only add ~1e-16 per step. On the reference problem it takes RK4's error at
  /// dt = 1 ms from 0.8e-9 … 8.7e-9 rad (varying with 1e-15 changes of the
  /// start) to 8.89e-10 ± 0.5 %, the truncation error.
  Eigen::Vector3d lost_pi = Eigen::Vector3d::Zero();
};

/// Π = q̄ L (q unit).
BodyCoords to_body_coords(const BodyState& s);
/// L = q Π after normalising q (the state the rest of tumble sees).
BodyState from_body_coords(const BodyCoords& x);
/// The seed's state of x: q by unit_quaternion, then L = q Π. The RK-type
/// steps in Euler's coordinates end with it (reference and tuned alike).
BodyState state_of(const BodyCoords& x);

/// q/|q| in scalars: n = (x² + y²) + (z² + w²), r = 1/√n, (x r, y r, z r, w r)
/// (one square root and one division, then products).
inline Eigen::Quaterniond unit_quaternion(double x, double y, double z, double w) {
  const double r = 1.0 / std::sqrt((x * x + y * y) + (z * z + w * w));
  return Eigen::Quaterniond(w * r, x * r, y * r, z * r);
}

/// Kinetic energy ½|P|²/M + ½ Π·I⁻¹Π (J), read off the coordinates (no rotation).
double kinetic_energy(const RigidBodyModel& m, const BodyCoords& x);
/// Every coordinate finite.
bool all_finite(const BodyCoords& x);

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
/// four stages of body_rate; per coordinate Δ = ((h/6)k1 + (h/3)k2) + (h/3)k3)
/// + (h/6)k4 and x' = x + Δ, except Π: d = ΔΠ − lost, Π' = Π + d,
/// lost' = (Π' − Π) − d (BodyCoords::lost_pi). q is not renormalised:
/// q' = ½ q ⊗ (0, ω) is linear in q and Π' does not read q, so |q| never
/// feeds back; state_of normalises for output, and the Propagator renormalises
/// the q it carries when |q|² drifts (which keeps a square root and a division,
/// ~45 cycles, off the step-to-step dependency chain).
BodyCoords rk4_coords_reference(const RigidBodyModel& m, const BodyCoords& x, double t, double h);
/// The same step from and to the seed's state: state_of(rk4_coords_reference(to_body_coords(s))).
BodyState rk4_body_reference(const RigidBodyModel& m, const BodyState& s, double t, double h);

/// The method `rk4`: the references above, through the tuned kernels for
/// torque-free bodies (same bits; see body_frame_tuned.hpp). The Propagator
/// carries BodyCoords from step to step (MethodInfo::coords_step), so a run
/// pays the q̄ L and q Π rotations only for output, and Π never takes the
/// round-off of a round trip through L_world; `step()` converts every time.
void rk4_coords_step(const RigidBodyModel& m, BodyCoords& x, double t, double h);
BodyState rk4_body_step(const RigidBodyModel& m, const BodyState& s, double t, double h);

}  // namespace tumble
