// A closed triangle mesh as a solid: its check (watertight, orientation,
// degenerate faces) and its exact mass properties. Pure Eigen; loading a file
// is the scene layer's job.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace tumble {

/// Indexed triangles; counter-clockwise seen from outside = outward normal.
struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;         ///< m (after unit conversion)
  std::vector<std::array<int, 3>> triangles;     ///< indices into `vertices`
};

/// What `inspect_mesh` finds. An edge is the unordered pair of its vertex indices.
struct MeshReport {
  std::size_t triangles = 0, vertices = 0;
  std::size_t boundary_edges = 0;       ///< used by one triangle only (holes)
  std::size_t non_manifold_edges = 0;   ///< used by three or more triangles
  std::size_t misoriented_edges = 0;    ///< two triangles traverse it the same way
  std::size_t degenerate_faces = 0;     ///< area <= 1e-12 × (bounding-box diagonal)²
  double signed_volume = 0;             ///< m³; < 0 when the normals point inwards
  double area = 0;                      ///< m²
  Eigen::Vector3d box_min = Eigen::Vector3d::Zero(), box_max = Eigen::Vector3d::Zero();  ///< m

  /// Every edge shared by exactly two triangles that traverse it oppositely.
  bool watertight() const { return triangles > 0 && boundary_edges == 0 && non_manifold_edges == 0 && misoriented_edges == 0; }
};

MeshReport inspect_mesh(const TriangleMesh& mesh);

/// Reverses every triangle (turns an inside-out mesh right way out).
void flip_orientation(TriangleMesh& mesh);

/// Drops triangles with a repeated index or zero area (exactly): they bound no volume.
std::size_t remove_degenerate_triangles(TriangleMesh& mesh);

/// Mass properties of the homogeneous solid a closed mesh bounds, density 1.
struct SolidProperties {
  double volume = 0;                                   ///< m³ (signed: < 0 for an inverted mesh)
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  ///< m
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();   ///< about the centroid, per unit density, m⁵

  /// Inertia tensor (kg·m²) of the solid with total mass `mass` (kg).
  Eigen::Matrix3d inertia_for_mass(double mass) const { return inertia * (mass / volume); }
};

/// Exact volume integrals of 1, x, y, z, x², …, xy over the polyhedron by the
/// divergence theorem: D. Eberly, "Polyhedral Mass Properties (Revisited)",
/// Geometric Tools, 2002 (after B. Mirtich, J. Graphics Tools 1(2), 1996).
/// Exact for any closed, consistently oriented mesh (convex or not) up to
/// round-off; integrals are taken about the vertex mean to limit cancellation.
SolidProperties solid_properties(const TriangleMesh& mesh);

}  // namespace tumble
