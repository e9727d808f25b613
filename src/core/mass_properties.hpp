// Mass properties of a particle cloud (seed §6) — what the body *is*, as
// opposed to how it moves (Jolt's MassProperties vs MotionProperties split).
#pragma once

#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/particle_cloud.hpp"

namespace tumble {

/// The cloud's extents along its principal axes.
struct PrincipalBox {
  Eigen::Vector3d center;        ///< box centre relative to the centre of mass, principal axes, m
  Eigen::Vector3d half_extents;  ///< m, along principal axes 1, 2, 3
};

struct MassProperties {
  double mass = 0;                   ///< M = Σ mᵢ, kg
  Eigen::Vector3d com;               ///< c = Σ mᵢ pᵢ / M, cloud axes, m
  Eigen::Matrix3d inertia;           ///< J0 = -Σ mᵢ [rᵢ]×[rᵢ]× about c, cloud axes, kg·m²
  Eigen::Vector3d principal_moments; ///< eigenvalues of J0, ascending, kg·m²
  Eigen::Matrix3d principal_axes;    ///< columns = unit principal axes in cloud axes; det = +1
  PrincipalBox box;

  /// Rotation cloud ← principal (the quaternion of `principal_axes`).
  Eigen::Quaterniond principal_rotation() const { return Eigen::Quaterniond(principal_axes); }
};

/// Smallest principal moment allowed, relative to the largest.
inline constexpr double kMinMomentRatio = 1e-12;

/// Computes M, c, J0, the right-handed principal frame and the box.
/// Throws DegenerateBody (naming `body_name`) for an empty cloud, non-positive or
/// non-finite masses, non-finite coordinates, or a vanishing principal moment
/// (single particle, collinear particles): such a body has no defined rotation.
MassProperties compute_mass_properties(const ParticleCloud& cloud, const std::string& body_name);

/// Inertia of point masses about `origin` (no validation): -Σ mᵢ [rᵢ]×[rᵢ]×.
Eigen::Matrix3d inertia_about(const ParticleCloud& cloud, const Eigen::Vector3d& origin);

}  // namespace tumble
