// A generated shape as the scene declares it (box, ellipsoid, cylinder,
// T-handle), kept beside the particle lattice built from it, so it can be drawn
// at its own dimensions: a lattice of n cells spans only (1 - 1/n) of an edge.
#pragma once

#include <Eigen/Core>

namespace tumble {

struct SolidShape {
  enum class Kind { box, ellipsoid, cylinder, t_handle };
  Kind kind = Kind::box;
  /// m. box: full edge lengths; ellipsoid: semi-axes; cylinder: (radius,
  /// radius, length along z); t_handle: (handle_length, stem_length, thickness).
  Eigen::Vector3d size = Eigen::Vector3d::Ones();
  /// Placement in the body's cloud axes: x_cloud = rotation · x_shape + offset
  /// (the generators centre each shape on its geometric centre).
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
};

}  // namespace tumble
