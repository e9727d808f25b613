// A rigid body's model (constant) and state (what the ODE integrates).
#pragma once

#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/forces.hpp"
#include "core/mass_properties.hpp"

namespace tumble {

/// Constant description of one body. The core integrates in the body's
/// principal frame, where the inertia is diagonal: Π = Rᵀ L, ω_body = Π / I.
struct RigidBodyModel {
  std::string name;
  double mass = 1;                        ///< M, kg
  Eigen::Vector3d inertia{1, 1, 1};       ///< principal moments I1 ≤ I2 ≤ I3, kg·m²
  Eigen::Vector3d inv_inertia{1, 1, 1};   ///< 1/I, 1/(kg·m²)
  /// cloud ← principal rotation (principal axes as columns in cloud axes).
  Eigen::Quaterniond cloud_from_principal = Eigen::Quaterniond::Identity();
  Eigen::Vector3d com_cloud = Eigen::Vector3d::Zero();  ///< centre of mass in cloud coords, m
  PrincipalBox box;
  ForceSet forces;
};

/// The seed's state x = (c, q, P, L), all world frame, SI.
struct BodyState {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();  ///< centre of mass, m
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();  ///< world ← principal frame
  Eigen::Vector3d P = Eigen::Vector3d::Zero();  ///< linear momentum, kg·m/s
  Eigen::Vector3d L = Eigen::Vector3d::Zero();  ///< angular momentum about c, kg·m²/s

  bool all_finite() const { return c.allFinite() && q.coeffs().allFinite() && P.allFinite() && L.allFinite(); }
};

/// Builds the model of a body from its mass properties.
RigidBodyModel make_model(const std::string& name, const MassProperties& mp, const ForceSet& forces);

/// User-facing initial conditions: cloud orientation and velocities as written in a scene.
struct InitialConditions {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();          ///< where c sits, world, m
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< world ← cloud
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();          ///< world, m/s
  Eigen::Vector3d omega = Eigen::Vector3d::Zero();             ///< rad/s, in `omega_frame`
  Frame omega_frame = Frame::body;  ///< body = the cloud's own axes
};

BodyState make_state(const RigidBodyModel& m, const InitialConditions& ic);

/// world ← cloud orientation (what users see) from the internal principal one.
inline Eigen::Quaterniond cloud_orientation(const RigidBodyModel& m, const BodyState& s) {
  return (s.q * m.cloud_from_principal.conjugate()).normalized();
}

}  // namespace tumble
