// Forces and torques a scene declares. Only declared terms are evaluated; a
// body with none takes the torque-free path (`ForceSet::empty()`).
#pragma once

#include <vector>

#include <Eigen/Core>

namespace tumble {

enum class Frame { world, body };

/// A constant force applied at a point fixed on the body (so it also yields torque).
struct PointForce {
  Eigen::Vector3d force;   ///< N, in `frame` (body = the cloud's own axes)
  Eigen::Vector3d point;   ///< m, cloud coordinates (as written in the scene)
  Frame frame = Frame::world;
};

struct ForceSet {
  bool has_gravity = false;
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();  ///< m/s², world; force M g
  std::vector<PointForce> point_forces;
  Eigen::Vector3d torque_world = Eigen::Vector3d::Zero();  ///< N·m, constant in world
  Eigen::Vector3d torque_body = Eigen::Vector3d::Zero();   ///< N·m, constant in the cloud's axes
  double linear_damping = 0;   ///< k in F = -k v, N·s/m
  double angular_damping = 0;  ///< k in τ = -k ω_world, N·m·s

  bool empty() const {
    return !has_gravity && point_forces.empty() && torque_world.isZero(0) && torque_body.isZero(0) &&
           linear_damping == 0 && angular_damping == 0;
  }
  /// True when some term produces a torque (the rotation is then not free).
  bool has_torque() const {
    return !point_forces.empty() || !torque_world.isZero(0) || !torque_body.isZero(0) || angular_damping != 0;
  }
  /// True when total energy (kinetic + gravity's potential) is an invariant:
  /// no term does work other than gravity. Decided here, not by the callers
  /// (the overlay's |dE/E| is an error only then).
  bool conserves_energy() const { return !has_torque() && linear_damping == 0; }
};

}  // namespace tumble
