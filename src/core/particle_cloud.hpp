// A body as a cloud of point masses (seed §6), and the generators that build one
// (a cloud file is read by io/cloud_file.hpp).
#pragma once

#include <vector>

#include <Eigen/Core>

namespace tumble {

/// One point mass. Position in the cloud's own axes (as written in the scene), m; mass, kg.
struct Particle {
  Eigen::Vector3d position;
  double mass;
};

using ParticleCloud = std::vector<Particle>;

/// Appends `src` shifted by `offset` (m) to `dst`: clouds from several sources are unioned.
void append_cloud(ParticleCloud& dst, const ParticleCloud& src, const Eigen::Vector3d& offset);

// ---- Generators. All put the geometric centre at the origin; `mass` is the total, kg.

/// Box lattice of n.x × n.y × n.z equal particles spanning `size` (full edge lengths, m).
/// As n grows, its inertia tends to the solid box's M(b²+c²)/12 etc.
ParticleCloud make_box(const Eigen::Vector3d& size, const Eigen::Vector3i& n, double mass);

/// Lattice points of an n×n×n grid over the bounding box that fall inside the
/// ellipsoid with semi-axes `semi_axes` (m).
ParticleCloud make_ellipsoid(const Eigen::Vector3d& semi_axes, int n, double mass);

/// Solid cylinder along z: `radius`, full `length` (m), lattice of n across the diameter.
ParticleCloud make_cylinder(double radius, double length, int n, double mass);

/// T-handle (the Dzhanibekov wing nut) made of two boxes: a `handle` bar along x
/// and a `stem` bar along y attached at the handle's middle, both of square
/// cross-section `thickness`. Lattice density `per_metre` particles per metre.
/// Mass split by volume; the origin is the geometric centre of the union's bounding box.
ParticleCloud make_t_handle(double handle_length, double stem_length, double thickness,
                            int per_metre, double mass);

}  // namespace tumble
