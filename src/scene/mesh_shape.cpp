// shape = { type = "mesh", ... }: a mesh file, checked, turned into particles,
// with the exact mass properties beside the cloud's for `tumble info`.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <cstdio>

#include "base/error.hpp"
#include "base/format.hpp"
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
  std::string file;    ///< as written, relative to the scene
  double scale = 1.0;  ///< m per file unit
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
    try {
      if (volume) f = fill_volume(mesh, watertight, l, 1.0, {.max_points = 4 * budget});
    } catch (const FillTooCostly& e) {  // bounded like the import: a clear stop, not minutes of work
      s.error(q.tolerance ? "inertia_tolerance" : "resolution",
              src.file + ": the volume fill at resolution " + std::to_string(res) + " stopped: " + e.what() +
                  "; lower the resolution" + (q.tolerance ? " (raise inertia_tolerance)" : "") +
                  (watertight ? "" : ", close the mesh,") + " or use fill = \"surface\"");
      return {};
    }
    if (f.overlapped > 0 && q.tolerance) {
      s.error("inertia_tolerance", src.file + ": the surface intersects itself (" + std::to_string(f.overlapped) +
                                       " lattice points are enclosed twice or negatively), so there is no exact "
                                       "tensor to meet; give resolution instead, or merge the shells into one");
      return {};
    }
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
      src.near = f.near;
      src.overlapped = f.overlapped;
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

/// Where each stage reports: the shape's keys (errors), the load context, and
/// the table and path that warnings point to.
struct Stage {
  TableReader& s;
  LoadContext& ctx;
  const toml::table& t;
  const std::string& path;
  void warn(const std::string& m) const { ctx.diag.warning(t.source(), path, m); }
};

/// The shape's keys, each checked against the others; nullopt after any error.
std::optional<Request> read_request(TableReader& s, LoadContext& ctx) {
  const std::size_t errors = ctx.diag.error_count();
  if (!s.has("file")) s.error("file", "missing; a mesh needs file = \"...\" (OBJ, STL, PLY, ...; relative to the scene)");
  Request q;
  q.file = s.string("file").value_or("");
  const std::string units = s.string("units").value_or("m");
  const auto scale = unit_scale(units);
  if (!scale) s.error("units", "expected \"m\", \"cm\", \"mm\" or \"in\" (the file's length unit), found " + quote_token(units));
  q.scale = scale.value_or(1.0);
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
  if (ctx.diag.error_count() != errors) return std::nullopt;
  return q;
}

/// The file's triangles in metres, degenerate faces removed; a PLY read for
/// its per-vertex masses (fill = "vertices") comes along.
struct LoadedMesh {
  TriangleMesh mesh;
  std::optional<PlyVertices> ply;
};

/// Reads and scales the mesh and fills src's file, fill, units and report; nullopt after an error.
std::optional<LoadedMesh> load_mesh(const Request& q, const Stage& st, MeshSource& src) {
  MeshFile mf;
  LoadedMesh m;  // assimp drops a PLY's per-vertex mass: read the vertices ourselves
  try {
    if (q.fill == "vertices" && is_ply_file(q.file)) m.ply = read_ply_vertices(st.ctx.base_dir / q.file);
    if (m.ply && m.ply->faces == 0) mf.mesh.vertices = m.ply->positions;  // a point cloud, which assimp refuses
    else mf = read_mesh_file(st.ctx.base_dir / q.file);
  } catch (const InputError& e) {
    st.s.error("file", e.what());
    return std::nullopt;
  }
  src.file = (st.ctx.base_dir / q.file).string();
  src.fill = q.fill;
  src.units = q.scale;
  m.mesh = std::move(mf.mesh);
  for (auto& v : m.mesh.vertices) v *= q.scale;
  const std::size_t degenerate = inspect_mesh(m.mesh).degenerate_faces;
  remove_degenerate_triangles(m.mesh);  // zero-area faces bound nothing; they would spoil the edge check
  src.report = inspect_mesh(m.mesh);
  src.report.degenerate_faces = degenerate;
  return m;
}

/// fill = "vertices": the points as they are, each with the PLY's mass or all
/// equal; nullopt after an error.
std::optional<ParticleCloud> vertex_cloud(const Request& q, const LoadedMesh& m, MeshSource& src, const Stage& st) {
  ParticleCloud cloud;
  if (m.ply && !m.ply->masses.empty()) {
    // Every PLY vertex with its own mass (kg); a shape `mass` rescales them to that total.
    for (const std::string& w : m.ply->warnings) st.ctx.diag.warning(st.t.source(), st.path, w);
    for (double w : m.ply->masses) src.file_mass += w;
    for (std::size_t i = 0; i < m.ply->masses.size(); ++i) {
      // Each mass's share of the file's total, then the shape's mass: 1/total
      // first overflowed for tiny (subnormal) masses and gave "mass inf".
      const double w = q.mass ? m.ply->masses[i] / src.file_mass * *q.mass : m.ply->masses[i];
      if (m.ply->masses[i] > 0) cloud.push_back({m.ply->positions[i] * q.scale, w});
      else ++src.massless_vertices;  // adds nothing; the core wants every mass > 0
    }
    if (!reserve_particles(st.ctx, st.s, "file", static_cast<double>(cloud.size()))) return std::nullopt;
  } else {
    // The distinct points (STL and OBJ repeat corners per face), equal masses.
    if (!reserve_particles(st.ctx, st.s, "file", static_cast<double>(m.mesh.vertices.size()))) return std::nullopt;
    const double w = q.mass.value_or(1.0) / static_cast<double>(m.mesh.vertices.size());
    for (const auto& p : m.mesh.vertices) cloud.push_back({p, w});
  }
  measure_cloud(cloud, src);
  return cloud;
}

/// Before a volume or surface fill: triangles present, an inside-out mesh
/// flipped, a tolerance only where an exact tensor exists, and that exact
/// tensor (unit mass) in src. The exact properties, or nullopt after an error.
std::optional<SolidProperties> exact_reference(const Request& q, TriangleMesh& mesh, const Eigen::Vector3d& offset,
                                               MeshSource& src, const Stage& st) {
  if (mesh.triangles.empty()) {
    st.s.error("file", src.file + ": has no triangles (" + std::to_string(mesh.vertices.size()) +
                           " points); fill = \"vertices\" uses the points as they are");
    return std::nullopt;
  }
  const bool volume = q.fill == "volume";
  if (volume && src.report.signed_volume < 0) {
    flip_orientation(mesh);
    src.flipped = true;
    st.warn(src.file + ": the mesh is inside out (signed volume " + format_number(src.report.signed_volume, 3) +
            " m³); its faces were flipped");
  }
  if (volume && !src.report.watertight() && q.tolerance) {
    st.s.error("inertia_tolerance", src.file + ": not watertight (" + holes(src.report) +
                                        "), so there is no exact tensor to meet; give resolution instead");
    return std::nullopt;
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
  return exact;
}

/// A volume fill of an open mesh: the winding number's ambiguous share of the
/// cloud is tolerated with a warning up to kMaxAmbiguous, an error above.
bool tolerate_holes(const Request& q, const MeshSource& src, const Stage& st) {
  if (q.fill != "volume" || src.report.watertight()) return true;
  // Of the points the test counts as inside or nearly (winding number over 0.25), so at most 100 %.
  const double frac = static_cast<double>(src.ambiguous) / static_cast<double>(std::max<std::size_t>(src.near, 1));
  const std::string what = "not watertight (" + holes(src.report) + "); the inside test is the generalized "
                           "winding number, which is ambiguous (between 0.25 and 0.75) at " + format_number(100 * frac, 3) +
                           " % of the " + std::to_string(src.near) + " lattice points it finds inside or nearly so";
  if (frac > kMaxAmbiguous) {
    st.s.error("fill", src.file + ": " + what + ": the holes are too large for it to tolerate (limit " +
                           format_number(100 * kMaxAmbiguous, 3) + " %); close the mesh or use fill = \"surface\"");
    return false;
  }
  st.warn(src.file + ": " + what + ", so it tolerates the holes; there is no exact tensor to compare with");
  return true;
}

/// fill = "volume" or "surface": the lattice cloud, weighed to the shape's
/// mass or density; nullopt after an error.
std::optional<ParticleCloud> filled_cloud(const Request& q, TriangleMesh& mesh, const Eigen::Vector3d& offset,
                                          MeshSource& src, const Stage& st) {
  const std::optional<SolidProperties> exact = exact_reference(q, mesh, offset, src, st);
  if (!exact) return std::nullopt;
  const std::size_t errors = st.ctx.diag.error_count();
  ParticleCloud cloud = fill_mesh(mesh, q, src, st.s, st.ctx);
  if (st.ctx.diag.error_count() != errors) return std::nullopt;
  if (cloud.empty()) {
    st.s.error("resolution", src.file + ": no lattice point falls inside the mesh; raise the resolution");
    return std::nullopt;
  }
  if (!tolerate_holes(q, src, st)) return std::nullopt;
  if (src.overlapped > 0) {
    // The exact (divergence-theorem) tensor counts overlapping regions twice;
    // the lattice counts the union once, so the union's mass is weighed.
    src.has_exact = false;
    st.warn(src.file + ": the surface intersects itself: " + std::to_string(src.overlapped) + " of the " +
            std::to_string(cloud.size()) + " lattice points inside are enclosed twice or negatively (shells that "
            "overlap, e.g. parts exported without a boolean union); the mass and inertia are the union's, from the "
            "lattice (exact volume " + format_number(std::abs(exact->volume), 4) + " m³ counts the overlap twice; "
            "lattice volume " + format_number(static_cast<double>(cloud.size()) * std::pow(src.spacing, 3), 4) + " m³)");
  }
  const double measure = src.has_exact ? std::abs(exact->volume)
                                       : static_cast<double>(cloud.size()) * std::pow(src.spacing, 3);
  const double mass = q.mass ? *q.mass : q.density ? *q.density * measure : 1.0;
  for (Particle& p : cloud) p.mass *= mass;
  src.cloud_inertia *= mass;
  src.exact_inertia *= mass;
  if (!reserve_particles(st.ctx, st.s, "resolution", static_cast<double>(cloud.size()))) return std::nullopt;
  return cloud;
}

}  // namespace

void read_mesh_shape(const toml::table& t, const std::string& path, LoadContext& ctx, const Eigen::Vector3d& offset,
                     ParticleCloud& out) {
  TableReader s(t, path, ctx.diag,
                {"type", "file", "units", "mass", "density", "fill", "resolution", "inertia_tolerance"});
  const Stage st{s, ctx, t, path};
  const std::optional<Request> q = read_request(s, ctx);
  if (!q) return;
  MeshSource src;
  std::optional<LoadedMesh> m = load_mesh(*q, st, src);
  if (!m) return;
  const std::optional<ParticleCloud> cloud =
      q->fill == "vertices" ? vertex_cloud(*q, *m, src, st) : filled_cloud(*q, m->mesh, offset, src, st);
  if (!cloud) return;
  for (const Particle& p : *cloud) src.mass += p.mass;
  src.cloud_com += offset;
  for (auto& v : m->mesh.vertices) v += offset;
  src.surface = std::move(m->mesh);
  append_cloud(out, *cloud, offset);
  if (ctx.meshes) ctx.meshes->push_back(std::move(src));
}

}  // namespace tumble::scene::detail
