// Particle clouds from triangle meshes: a lattice filling the solid, samples on
// its surface, and the exact shell properties the surface samples approach.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "base/error.hpp"
#include "core/particle_cloud.hpp"
#include "core/triangle_mesh.hpp"

namespace tumble {

/// Generalized winding number (A. Jacobson, L. Kavan, O. Sorkine-Hornung,
/// "Robust Inside-Outside Segmentation using Generalized Winding Numbers",
/// SIGGRAPH 2013): Σ solid angles / 4π, each by Van Oosterom & Strackee (1983).
/// 1 inside a closed outward mesh, 0 outside; near a hole it blends smoothly.
double winding_number(const TriangleMesh& mesh, const Eigen::Vector3d& p);

/// A cubic lattice of spacing `spacing` (m) over the mesh's bounding box in the
/// lattice's axes, shifted by `offset` × spacing (each component in [0, 1)).
struct LatticeSpec {
  double spacing = 0;
  Eigen::Vector3d offset = Eigen::Vector3d::Constant(0.5);
  /// Lattice axes in mesh axes. A flat face parallel to the lattice planes is
  /// counted to within a whole plane of points (an error first order in the
  /// spacing: ~1% at 1e6 particles for the wing nut's 3 mm wings); a generic
  /// turn makes the errors average out, as N^(-2/3).
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

struct VolumeFill {
  ParticleCloud cloud;                 ///< equal masses summing to the requested mass
  std::size_t winding_evaluations = 0; ///< GWN evaluations made (0 for a watertight mesh)
  std::size_t winding_work = 0;        ///< tree nodes and triangles those evaluations visited
  std::size_t ambiguous = 0;           ///< points with winding number in (0.25, 0.75): near a hole
  std::size_t near = 0;                ///< points with winding number over 0.25: inside, or ambiguous
  /// Points enclosed twice or more, or negatively (winding number ≥ 1.5 or
  /// ≤ −0.5): the surface intersects itself there (two shells overlapping, or
  /// one inside another facing the same way), so its divergence-theorem
  /// volume counts them twice (or takes them away).
  std::size_t overlapped = 0;
  double lattice_points = 0;           ///< points visited, nx·ny·nz (the cloud is empty when over `max_points`)
};

/// What a fill may spend before it stops with FillTooCostly: lattice points
/// (checked before any work), row crossings (memory: 24 bytes each) and
/// winding-number work (time: tree nodes and triangles visited, some 25 ns
/// each here, so 3·10⁸ is about 8 s; an open cube at resolution 60 takes
/// 6·10⁶, 100 copies of it lying on each other 10⁹).
struct FillLimits {
  double max_points = INFINITY;
  double max_crossings = 4e7;
  double max_winding_work = 3e8;
};

/// A fill that would pass a FillLimits: what ran out and how far it got.
class FillTooCostly : public InputError {
 public:
  using InputError::InputError;
};

/// Lattice points inside the mesh, each of mass `mass` / count.
/// Watertight meshes: per lattice row, signed ray crossings (a top-left rule on
/// shared edges makes the count exact; it equals the winding number there).
/// Otherwise the winding number decides (by a `WindingTree`, to within ~0.04),
/// evaluated at the ends and middle of each stretch of a row between crossings
/// and at every point of a stretch where those disagree or are not near an
/// integer (holes make it fractional).
/// A lattice of more than `max_points` points is not filled: only
/// `lattice_points` is set (a particle budget checked without turning the mesh twice).
/// Throws FillTooCostly past `limits.max_crossings` or `limits.max_winding_work`.
VolumeFill fill_volume(const TriangleMesh& mesh, bool watertight, const LatticeSpec& lattice, double mass,
                       const FillLimits& limits = {});

/// Number of lattice points per axis `fill_volume` visits.
Eigen::Vector3d lattice_counts(const TriangleMesh& mesh, const LatticeSpec& lattice);

/// `count` points on the surface, area-weighted, uniform within each triangle,
/// each of mass `mass` / count; deterministic for a given `seed`.
ParticleCloud fill_surface(const TriangleMesh& mesh, std::size_t count, double mass, std::uint64_t seed);

/// A uniform thin shell (density per area 1): exact area, centroid and inertia
/// about the centroid (per unit area density, kg·m² per kg/m²), the limit of `fill_surface`.
SolidProperties shell_properties(const TriangleMesh& mesh);

/// Deterministic uniform doubles in [0, 1) (mt19937_64 is fully specified by
/// the standard; the conversion is ours, unlike uniform_real_distribution's).
class UnitRandom {
 public:
  explicit UnitRandom(std::uint64_t seed) : engine_(seed) {}
  double operator()() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

 private:
  std::mt19937_64 engine_;
};

}  // namespace tumble
