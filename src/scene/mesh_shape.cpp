// shape = { type = "mesh", ... }: a mesh file, checked, turned into particles,
// with the exact mass properties beside the cloud's for `tumble info`.
#include <cmath>
#include <numbers>
#include <optional>
#include <cstdio>

#include "core/error.hpp"
#include "core/format.hpp"
#include "core/mass_properties.hpp"
#include "core/mesh_fill.hpp"
#include "scene/internal.hpp"
#include "scene/mesh_file.hpp"
#include "scene/ply_vertices.hpp"

namespace tumble::scene::detail {

namespace {

constexpr long long kDefaultResolution = 30;       ///< lattice points along the longest box edge
constexpr double kMaxAmbiguous = 0.01;             ///< of the lattice, before holes are "too large"
constexpr double kLadderStep = 1.2;                ///< resolution growth while meeting a tolerance

std::optional<double> unit_scale(const std::string& u) {
  if (u == "m") return 1.0;
  if (u == "cm") return 0.01;
  if (u == "mm") return 0.001;
  if (u == "in") return 0.0254;
  return std::nullopt;
}

std::string holes(const MeshReport& r) {
  return std::to_string(r.boundary_edges) + " boundary, " + std::to_string(r.non_manifold_edges) +
         " non-manifold and " + std::to_string(r.misoriented_edges) + " misoriented edges";
}

void measure_cloud(const ParticleCloud& c, MeshSource& src) {
  double m = 0;
  Eigen::Vector3d com = Eigen::Vector3d::Zero();
  for (const Particle& p : c) m += p.mass, com += p.mass * p.position;
  src.cloud_com = com / m;
  src.cloud_inertia = inertia_about(c, src.cloud_com);
  src.particles = c.size();
}

// Randomly offset and turned lattice (deterministic per resolution): its error
// converges as N^(-2/3), also for flat faces, which an axis-aligned lattice
// would count to within a whole plane of points.
LatticeSpec lattice_for(const MeshReport& r, long long resolution) {
  UnitRandom rnd(static_cast<std::uint64_t>(resolution));
  const double h = (r.box_max - r.box_min).maxCoeff() / static_cast<double>(resolution);
  const Eigen::Vector3d offset(rnd(), rnd(), rnd());
  // Uniform random rotation (K. Shoemake, "Uniform random rotations", Graphics Gems III, 1992).
  const double u1 = rnd(), a = 2 * std::numbers::pi * rnd(), b = 2 * std::numbers::pi * rnd();
  const Eigen::Quaterniond q(std::sqrt(u1) * std::cos(b), std::sqrt(1 - u1) * std::sin(a),
                             std::sqrt(1 - u1) * std::cos(a), std::sqrt(u1) * std::sin(b));
  return {h, offset, q.normalized()};
}

struct Request {
  std::string fill;
  std::optional<double> mass, density;  ///< kg; kg/m³ (volume) or kg/m² (surface)
  long long resolution = kDefaultResolution;
  std::optional<double> tolerance;
};

// Volume and surface fills share the ladder: the coarsest resolution whose
// cloud is within the tolerance of the exact tensor (or the fixed one).
ParticleCloud fill_mesh(const TriangleMesh& mesh, const Request& q, MeshSource& src, TableReader& s,
                        LoadContext& ctx) {
  const bool volume = q.fill == "volume";
  const bool watertight = src.report.watertight();
  long long res = q.tolerance ? 8 : q.resolution;
  for (;;) {
    const LatticeSpec l = lattice_for(src.report, res);
    const double budget = static_cast<double>(kMaxParticles - ctx.particles);
    VolumeFill f;
    if (volume) f = fill_volume(mesh, watertight, l, 1.0, 4 * budget);
    const double estimate = volume ? f.lattice_points : src.report.area / (l.spacing * l.spacing);
    if (estimate > 4 * budget) {
      s.error(q.tolerance ? "inertia_tolerance" : "resolution",
              q.tolerance ? "no cloud within the particle cap meets inertia_tolerance; raise it"
                          : "resolution " + std::to_string(res) + " gives about " + format_number(estimate, 3) +
                                " particles, over the cap; lower it");
      return {};
    }
    ParticleCloud c;
    if (volume) {
      c = std::move(f.cloud);
      src.ambiguous = f.ambiguous;
    } else {
      c = fill_surface(mesh, static_cast<std::size_t>(std::max(1.0, std::round(estimate))), 1.0,
                       static_cast<std::uint64_t>(res));
    }
    src.spacing = l.spacing;
    if (!c.empty()) measure_cloud(c, src);
    if (!q.tolerance || c.empty() || src.inertia_error() <= *q.tolerance) return c;
    res = static_cast<long long>(std::ceil(static_cast<double>(res) * kLadderStep));
  }
}

}  // namespace

void read_mesh_shape(const toml::table& t, const std::string& path, LoadContext& ctx, const Eigen::Vector3d& offset,
                     ParticleCloud& out) {
  TableReader s(t, path, ctx.diag,
                {"type", "file", "units", "mass", "density", "fill", "resolution", "inertia_tolerance"});
  const std::size_t errors = ctx.diag.error_count();
  if (!s.has("file")) s.error("file", "missing; a mesh needs file = \"...\" (OBJ, STL, PLY, ...; relative to the scene)");
  const std::string file = s.string("file").value_or("");
  const std::string units = s.string("units").value_or("m");
  const auto scale = unit_scale(units);
  if (!scale) s.error("units", "expected \"m\", \"cm\", \"mm\" or \"in\" (the file's length unit), found " + quote_token(units));
  Request q;
  q.fill = s.string("fill").value_or("volume");
  if (q.fill != "volume" && q.fill != "surface" && q.fill != "vertices")
    s.error("fill", "expected \"volume\", \"surface\" or \"vertices\", found " + quote_token(q.fill));
  if (s.has("mass") && s.has("density")) s.error("density", "give mass or density, not both");
  if (s.has("mass")) q.mass = s.number("mass", Range::positive());
  if (s.has("density")) q.density = s.number("density", Range::positive());
  if (q.density && q.fill == "vertices")
    s.error("density", "fill = \"vertices\" has no volume or area to weigh; give mass (kg)");
  if (s.has("resolution") && s.has("inertia_tolerance"))
    s.error("inertia_tolerance", "give resolution or inertia_tolerance, not both");
  if (s.has("resolution")) q.resolution = s.integer("resolution", 2, 5000).value_or(kDefaultResolution);
  if (s.has("inertia_tolerance")) q.tolerance = s.number("inertia_tolerance", Range::closed(1e-8, 0.5));
  if (q.tolerance && q.fill == "vertices")
    s.error("inertia_tolerance", "fill = \"vertices\" uses the points as they are; it needs fill = \"volume\" or \"surface\"");
  if (ctx.diag.error_count() != errors) return;

  MeshFile mf;
  std::optional<PlyVertices> ply;  // assimp drops a PLY's per-vertex mass: read the vertices ourselves
  try {
    if (q.fill == "vertices" && is_ply_file(file)) ply = read_ply_vertices(ctx.base_dir / file);
    if (ply && ply->faces == 0) mf.mesh.vertices = ply->positions;  // a point cloud, which assimp refuses
    else mf = read_mesh_file(ctx.base_dir / file);
  } catch (const InputError& e) {
    s.error("file", e.what());
    return;
  }
  MeshSource src;
  src.file = (ctx.base_dir / file).string();
  src.fill = q.fill;
  src.units = *scale;
  TriangleMesh mesh = std::move(mf.mesh);
  for (auto& v : mesh.vertices) v *= *scale;
  const std::size_t degenerate = inspect_mesh(mesh).degenerate_faces;
  remove_degenerate_triangles(mesh);  // zero-area faces bound nothing; they would spoil the edge check
  src.report = inspect_mesh(mesh);
  src.report.degenerate_faces = degenerate;
  auto warn = [&](const std::string& m) { ctx.diag.warning(t.source(), path, src.file + ": " + m); };

  ParticleCloud cloud;
  if (q.fill == "vertices") {
    if (ply && !ply->masses.empty()) {
      // Every PLY vertex with its own mass (kg); a shape `mass` rescales them to that total.
      for (const std::string& w : ply->warnings) ctx.diag.warning(t.source(), path, w);
      for (double m : ply->masses) src.file_mass += m;
      const double k = q.mass ? *q.mass / src.file_mass : 1.0;
      for (std::size_t i = 0; i < ply->masses.size(); ++i) {
        if (ply->masses[i] > 0) cloud.push_back({ply->positions[i] * *scale, ply->masses[i] * k});
        else ++src.massless_vertices;  // adds nothing; the core wants every mass > 0
      }
      if (!reserve_particles(ctx, s, "file", static_cast<double>(cloud.size()))) return;
    } else {
      // The distinct points (STL and OBJ repeat corners per face), equal masses.
      if (!reserve_particles(ctx, s, "file", static_cast<double>(mesh.vertices.size()))) return;
      const double m = q.mass.value_or(1.0) / static_cast<double>(mesh.vertices.size());
      for (const auto& p : mesh.vertices) cloud.push_back({p, m});
    }
    measure_cloud(cloud, src);
  } else {
    if (mesh.triangles.empty()) {
      s.error("file", src.file + ": has no triangles (" + std::to_string(mesh.vertices.size()) +
                          " points); fill = \"vertices\" uses the points as they are");
      return;
    }
    const bool volume = q.fill == "volume";
    if (volume && src.report.signed_volume < 0) {
      flip_orientation(mesh);
      src.flipped = true;
      warn("the mesh is inside out (signed volume " + format_number(src.report.signed_volume, 3) +
           " m³); its faces were flipped");
    }
    if (volume && !src.report.watertight() && q.tolerance) {
      s.error("inertia_tolerance", src.file + ": not watertight (" + holes(src.report) +
                                       "), so there is no exact tensor to meet; give resolution instead");
      return;
    }
    src.inside_test = !volume ? "" : src.report.watertight() ? "ray crossings per lattice row (exact on a closed mesh)"
                                                              : "generalized winding number (Jacobson et al. 2013)";
    // Exact reference first (for unit mass): the tolerance ladder compares with it.
    const SolidProperties exact = volume ? solid_properties(mesh) : shell_properties(mesh);
    src.has_exact = !volume || src.report.watertight();
    if (src.has_exact) {
      src.exact_com = exact.centroid + offset;
      src.exact_inertia = exact.inertia_for_mass(1.0);
    }
    cloud = fill_mesh(mesh, q, src, s, ctx);
    if (ctx.diag.error_count() != errors) return;
    if (cloud.empty()) {
      s.error("resolution", src.file + ": no lattice point falls inside the mesh; raise the resolution");
      return;
    }
    if (volume && !src.report.watertight()) {
      const double frac = static_cast<double>(src.ambiguous) / static_cast<double>(cloud.size());
      const std::string what = "not watertight (" + holes(src.report) + "); the inside test is the generalized "
                               "winding number, which is ambiguous (between 0.25 and 0.75) at " + format_number(100 * frac, 3) +
                               " % of the " + std::to_string(cloud.size()) + " particles";
      if (frac > kMaxAmbiguous) {
        s.error("fill", src.file + ": " + what + ": the holes are too large for it to tolerate (limit " +
                            format_number(100 * kMaxAmbiguous, 3) + " %); close the mesh or use fill = \"surface\"");
        return;
      }
      warn(what + ", so it tolerates the holes; there is no exact tensor to compare with");
    }
    const double measure = src.has_exact ? std::abs(exact.volume)
                                         : static_cast<double>(cloud.size()) * std::pow(src.spacing, 3);
    const double mass = q.mass ? *q.mass : q.density ? *q.density * measure : 1.0;
    for (Particle& p : cloud) p.mass *= mass;
    src.cloud_inertia *= mass;
    src.exact_inertia *= mass;
    if (!reserve_particles(ctx, s, "resolution", static_cast<double>(cloud.size()))) return;
  }
  for (const Particle& p : cloud) src.mass += p.mass;
  src.cloud_com += offset;
  for (auto& v : mesh.vertices) v += offset;
  src.surface = std::move(mesh);
  append_cloud(out, cloud, offset);
  if (ctx.meshes) ctx.meshes->push_back(std::move(src));
}

}  // namespace tumble::scene::detail
