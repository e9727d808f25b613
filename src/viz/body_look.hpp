// What is drawn of a body besides its box and axes, prepared once per body:
// its mesh surfaces and the particles that can be seen (GL-free).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "core/particle_cloud.hpp"
#include "core/solid_shape.hpp"
#include "core/triangle_mesh.hpp"
#include "viz/draw_list.hpp"

namespace tumble::viz {

/// Indices of the particles on the outside of the cloud: those whose cell in a
/// grid of about the lattice spacing has an empty face neighbour (exposed_directions).
std::vector<std::uint32_t> visible_particles(const ParticleCloud& cloud);

/// Flat-shaded triangle soup of a mesh in cloud axes (m), as a draw-list item shares it.
std::shared_ptr<const SurfaceMesh> make_surface(const TriangleMesh& mesh);

/// A generated shape's lit surface at its declared dimensions, in cloud axes
/// (m): flat faces, smooth normals on an ellipsoid and a cylinder's side.
std::shared_ptr<const SurfaceMesh> solid_surface(const SolidShape& shape);

struct BodyLook {
  std::vector<std::shared_ptr<const SurfaceMesh>> surfaces;
  std::vector<Color> surface_colors;     ///< one per surface
  std::shared_ptr<const ParticleSet> particles;  ///< null: particles not drawn
  /// The extent of the surfaces along the principal axes, about the centre of
  /// mass (m): the principal box drawn as an outline around them. Unset
  /// without surfaces (the box then bounds the particles).
  std::optional<std::pair<Eigen::Vector3d, Eigen::Vector3d>> surface_box;  ///< centre, half extents
};

/// The box of `surfaces` along the principal axes `axes` (columns, cloud
/// axes) about `com` (cloud axes): its centre relative to com, in principal
/// coordinates, and its half extents, m.
std::pair<Eigen::Vector3d, Eigen::Vector3d> principal_extent(const std::vector<std::shared_ptr<const SurfaceMesh>>& surfaces,
                                                             const Eigen::Matrix3d& axes, const Eigen::Vector3d& com);

}  // namespace tumble::viz
