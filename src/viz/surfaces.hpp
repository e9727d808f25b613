// Shared unit meshes placed by a model matrix: a smooth sphere (an ellipsoid
// under a non-uniform scale; the mesh shader keeps its normals right) and a
// square (filled rectangles: Poinsot's plane, shaded plot bands).
#pragma once

#include <memory>

#include "viz/draw_list.hpp"

namespace tumble::viz {

/// The unit sphere, smooth normals, outward and counter-clockwise; made once.
std::shared_ptr<const SurfaceMesh> unit_sphere_mesh();
/// The square [-1, 1]² in z = 0, normal +z, counter-clockwise; made once.
std::shared_ptr<const SurfaceMesh> unit_square_mesh();

/// The rectangle c ± u ± v (world), facing u × v.
SurfaceItem rectangle(const glm::dvec3& c, const glm::dvec3& u, const glm::dvec3& v, const Color& color);
/// The ellipsoid {c + A s ⊙ e : |e| = 1}: columns of `axes` (orthonormal) scaled by `semi_axes`.
SurfaceItem ellipsoid(const glm::dvec3& c, const glm::dmat3& axes, const glm::dvec3& semi_axes, const Color& color);

}  // namespace tumble::viz
