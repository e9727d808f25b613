// The one rule for a camera whose up vector is parallel to its view direction
// (a top-down view with the default up = +z): lookAt would divide by zero and
// draw a blank frame. Shared by the scene loader (which warns) and the viz
// layer (which guards every frame, for cameras that move).
#pragma once

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross

namespace tumble::viz {

/// `up` unless it is (nearly) parallel to `view_dir` (sin of the angle < 1e-6),
/// else +y, or +x when looking along y.
inline Eigen::Vector3d usable_up(const Eigen::Vector3d& up, const Eigen::Vector3d& view_dir) {
  const double n = up.norm() * view_dir.norm();
  if (n > 0 && up.cross(view_dir).norm() >= 1e-6 * n) return up;
  const Eigen::Vector3d y = Eigen::Vector3d::UnitY();
  return std::abs(y.dot(view_dir)) < 0.9 * view_dir.norm() ? y : Eigen::Vector3d(Eigen::Vector3d::UnitX());
}

}  // namespace tumble::viz
