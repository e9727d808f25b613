// [[bodies]]: particle sources, initial conditions, per-body forces, colour.
#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <iterator>

#include "core/dynamics.hpp"
#include "core/error.hpp"
#include "scene/internal.hpp"

namespace tumble::scene::detail {

namespace {

// Default body colours (linear RGB), cycled by body index: sand, grey, sage,
// mauve, olive, rose; muted tones apart from the colour of every vector and
// curve of docs/colours.md (tests/run/body_colour_test.cpp).
constexpr std::array<std::array<double, 3>, 6> kPalette = {{
    {0.72, 0.64, 0.48}, {0.60, 0.62, 0.68}, {0.50, 0.62, 0.56},
    {0.62, 0.52, 0.60}, {0.56, 0.52, 0.40}, {0.70, 0.52, 0.50}}};

bool valid_name(const std::string& n) {
  if (n.empty() || n.size() > 64) return false;
  return std::all_of(n.begin(), n.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
           c == '.';
  });
}

// Reads one table's particle sources (and mesh shapes) into the body, rotated
// by `q` about the table's own origin, then shifted by `offset` (m).
int read_placed(TableReader& r, LoadContext& ctx, const Eigen::Quaterniond& q, const Eigen::Vector3d& offset,
                const std::optional<Eigen::Vector3d>& color, Body& b) {
  ParticleCloud cloud;
  std::vector<MeshSource> meshes;
  std::vector<ShapeSource> shapes;
  ctx.meshes = &meshes;
  ctx.shapes = &shapes;
  const int sources = read_cloud_sources(r, ctx, Eigen::Vector3d::Zero(), cloud);
  ctx.meshes = nullptr;
  ctx.shapes = nullptr;
  const Eigen::Matrix3d R = q.toRotationMatrix();
  const std::size_t begin = b.cloud.size();
  b.cloud.reserve(begin + cloud.size());
  for (const Particle& p : cloud) b.cloud.push_back({R * p.position + offset, p.mass});
  if (color) b.part_colors.push_back({begin, b.cloud.size(), *color});
  for (MeshSource& m : meshes) {
    for (auto& v : m.surface.vertices) v = R * v + offset;
    m.exact_com = R * m.exact_com + offset;
    m.cloud_com = R * m.cloud_com + offset;
    m.exact_inertia = R * m.exact_inertia * R.transpose();
    m.cloud_inertia = R * m.cloud_inertia * R.transpose();
    if (color) m.color = *color;
    else m.color = Eigen::Vector3d::Constant(-1);  // the body's, set once it is read
    b.meshes.push_back(std::move(m));
  }
  for (ShapeSource& sh : shapes) {
    sh.shape.rotation = R * sh.shape.rotation;
    sh.shape.offset = R * sh.shape.offset + offset;
    sh.color = color ? *color : Eigen::Vector3d::Constant(-1);  // the body's, set once it is read
    b.shapes.push_back(sh);
  }
  return sources;
}

std::optional<Eigen::Quaterniond> read_orientation(TableReader& r) {
  const toml::node* n = r.node("orientation");
  if (!n) return Eigen::Quaterniond::Identity();
  const toml::array* a = n->as_array();
  if (!a || a->size() != 4) {
    r.error("orientation", "expected a quaternion [w, x, y, z], found " + describe(*n));
    return std::nullopt;
  }
  double c[4];
  for (std::size_t k = 0; k < 4; ++k) {
    auto v = read_number(*a->get(k), r.key_path("orientation") + "[" + std::to_string(k) + "]", Range::any(),
                         r.diag());
    if (!v) return std::nullopt;
    c[k] = *v;
  }
  Eigen::Quaterniond q(c[0], c[1], c[2], c[3]);
  const double norm = q.norm();
  if (!std::isfinite(norm)) {
    r.error("orientation", "expected a quaternion [w, x, y, z] of moderate size (it is normalised), found one "
                           "whose norm overflows; divide the components by their largest");
    return std::nullopt;
  }
  if (!(norm > 1e-12)) {
    r.error("orientation", "expected a non-zero quaternion [w, x, y, z], found [0, 0, 0, 0]");
    return std::nullopt;
  }
  if (std::abs(norm - 1) > 1e-9) {
    r.diag().warning(n->source(), r.key_path("orientation"),
                     "quaternion has norm " + std::to_string(norm) + "; normalised to unit length");
  }
  return q.normalized();
}

// Terms in the order they are summed: gravity (scene-wide), the point forces,
// then one per body key of force_kinds().
void read_forces(TableReader& r, const Scene& scene, ForceSet& f) {
  if (scene.has_gravity) f.terms.push_back(UniformGravity{scene.gravity});
  std::vector<ForceTerm> keyed;  // read first, as the keys are reported in this order
  for (const ForceKind& kind : force_kinds()) {
    if (kind.vector) {
      const std::optional<Eigen::Vector3d> v = r.vec3(kind.key);
      if (v && !v->isZero(0)) keyed.push_back(kind.make(*v, 0));
    } else {
      const std::optional<double> x = r.number(kind.key, Range::non_negative());
      if (x && *x != 0) keyed.push_back(kind.make(Eigen::Vector3d::Zero(), *x));
    }
  }
  const auto list = r.tables("forces");
  for (std::size_t i = 0; i < list.size(); ++i) {
    TableReader fr(*list[i], r.key_path("forces") + "[" + std::to_string(i) + "]", r.diag(),
                   {"type", "force", "point", "frame"});
    const std::string type = fr.string("type").value_or("point");
    if (type != "point") {
      fr.error("type", "expected \"point\" (torques and damping are body keys), found " + quote_token(type));
      continue;
    }
    PointForce pf;
    if (!fr.has("force")) fr.error("force", "missing; a point force needs force = [fx, fy, fz] (N)");
    pf.force = fr.vec3("force").value_or(Eigen::Vector3d::Zero());
    pf.point = fr.vec3("point").value_or(Eigen::Vector3d::Zero());
    const std::string frame = fr.string("frame").value_or("world");
    if (frame == "world") pf.frame = Frame::world;
    else if (frame == "body") pf.frame = Frame::body;
    else fr.error("frame", "expected \"world\" or \"body\", found " + quote_token(frame));
    f.terms.push_back(pf);
  }
  f.terms.insert(f.terms.end(), keyed.begin(), keyed.end());
}

void read_body_name(TableReader& r, std::size_t index, LoadContext& ctx, Body& b) {
  b.name = r.string("name").value_or("body" + std::to_string(index));
  if (!valid_name(b.name)) {
    r.error("name", "expected 1-64 characters from [A-Za-z0-9_.-], found " + quote_token(b.name));
  } else if (std::find(ctx.body_names.begin(), ctx.body_names.end(), b.name) != ctx.body_names.end()) {
    r.error("name", "duplicate body name \"" + b.name + "\"; names must be unique");
  }
  ctx.body_names.push_back(b.name);
  // What people read: any text but line breaks, so "tennis racket" may name the body "racket".
  b.label = r.string("display_name").value_or(b.name);
  if (r.has("display_name") && (b.label.empty() || b.label.size() > 64 || b.label.find('\n') != std::string::npos))
    r.error("display_name", "expected 1-64 characters on one line, found " + quote_token(b.label));
}

/// The body's particles: its own (particles, shape, cloud) and its [[bodies.parts]].
void read_body_particles(const toml::table& t, TableReader& r, LoadContext& ctx, Body& b) {
  int sources = read_placed(r, ctx, Eigen::Quaterniond::Identity(), Eigen::Vector3d::Zero(), std::nullopt, b);
  const auto parts = r.tables("parts");
  for (std::size_t j = 0; j < parts.size(); ++j) {
    TableReader pr(*parts[j], r.key_path("parts") + "[" + std::to_string(j) + "]", ctx.diag,
                   {"particles", "shape", "cloud", "offset", "orientation", "color"});
    const Eigen::Vector3d offset = pr.vec3("offset").value_or(Eigen::Vector3d::Zero());
    const Eigen::Quaterniond q = read_orientation(pr).value_or(Eigen::Quaterniond::Identity());
    const std::optional<Eigen::Vector3d> color = pr.vec3("color", Range::closed(0, 1));
    if (read_placed(pr, ctx, q, offset, color, b) == 0)
      ctx.diag.error(parts[j]->source(), pr.path(), "a part needs particles, shape or cloud");
    ++sources;
  }
  if (sources == 0)
    ctx.diag.error(t.source(), r.path(),
                   "body \"" + b.name + "\" has no particles; give particles, shape, cloud or [[bodies.parts]]");
}

InitialConditions read_initial_conditions(TableReader& r) {
  InitialConditions ic;
  ic.position = r.vec3("position").value_or(Eigen::Vector3d::Zero());
  ic.orientation = read_orientation(r).value_or(Eigen::Quaterniond::Identity());
  ic.velocity = r.vec3("velocity").value_or(Eigen::Vector3d::Zero());
  if (r.has("omega_body") && r.has("omega_world")) {
    r.error("omega_world", "give omega_body or omega_world, not both");
  } else if (r.has("omega_world")) {
    ic.omega = r.vec3("omega_world").value_or(Eigen::Vector3d::Zero());
    ic.omega_frame = Frame::world;
  } else {
    ic.omega = r.vec3("omega_body").value_or(Eigen::Vector3d::Zero());
    ic.omega_frame = Frame::body;
  }
  return ic;
}

/// Mass properties, model and initial state of a body read without errors;
/// false (an error given) when they cannot be had or leave the double range.
bool complete_body(const toml::table& t, const TableReader& r, LoadContext& ctx, const ForceSet& forces, Body& b) {
  try {
    b.mass_properties = compute_mass_properties(b.cloud, b.name);
  } catch (const InputError& e) {  // DegenerateBody: its message names the body and the fix
    ctx.diag.error(t.source(), r.path(), e.what());
    return false;
  }
  b.model = make_model(b.name, b.mass_properties, forces);
  b.initial = make_state(b.model, b.initial_conditions);
  if (!b.initial.all_finite()) {
    ctx.diag.error(t.source(), r.path(), "initial state of \"" + b.name + "\" is not finite; check the values");
    return false;
  }
  // The steps square momenta and divide energies: each must stay a normal double (or 0).
  const double sizes[] = {b.initial.L.squaredNorm(), b.initial.P.squaredNorm(), kinetic_energy(b.model, b.initial)};
  if (std::any_of(std::begin(sizes), std::end(sizes), [](double v) { return !std::isfinite(v) || (v != 0 && v < DBL_MIN); })) {
    ctx.diag.error(t.source(), r.path(), "body '" + b.name + "': the initial momenta or kinetic energy (" +
                                             format_number(sizes[2]) + " J) leave the normal double range "
                                             "(2.2e-308 to 1.8e308); express the body in other units");
    return false;
  }
  return true;
}

void read_body(const toml::table& t, std::size_t index, LoadContext& ctx, Scene& scene) {
  const std::size_t errors_before = ctx.diag.error_count();
  std::vector<std::string_view> keys = {"name",        "display_name", "particles", "shape",      "cloud",       "parts",
                                        "position",    "orientation", "velocity", "omega_body", "omega_world",
                                        "forces"};
  for (const ForceKind& kind : force_kinds()) keys.push_back(kind.key);
  keys.push_back("color");
  TableReader r(t, "bodies[" + std::to_string(index) + "]", ctx.diag, keys);
  Body b;
  read_body_name(r, index, ctx, b);
  read_body_particles(t, r, ctx, b);
  b.initial_conditions = read_initial_conditions(r);
  ForceSet forces;
  read_forces(r, scene, forces);
  const auto& pal = kPalette[index % kPalette.size()];
  b.color = r.vec3("color", Range::closed(0, 1)).value_or(Eigen::Vector3d(pal[0], pal[1], pal[2]));
  for (MeshSource& m : b.meshes)
    if (m.color.x() < 0) m.color = b.color;
  for (ShapeSource& sh : b.shapes)
    if (sh.color.x() < 0) sh.color = b.color;

  if (ctx.diag.error_count() != errors_before) return;  // the body is broken; keep collecting others
  if (complete_body(t, r, ctx, forces, b)) scene.bodies.push_back(std::move(b));
}

}  // namespace

void read_bodies(TableReader& root, LoadContext& ctx, Scene& scene) {
  if (!root.has("bodies")) {
    root.error("bodies", "missing; a scene needs at least one [[bodies]] table");
    return;
  }
  const auto list = root.tables("bodies");
  if (list.size() > kMaxBodies) {
    root.error("bodies", "expected at most " + std::to_string(kMaxBodies) + " bodies (the cap), found " +
                             std::to_string(list.size()));
    return;
  }
  scene.bodies.reserve(list.size());
  for (std::size_t i = 0; i < list.size(); ++i) read_body(*list[i], i, ctx, scene);
}

}  // namespace tumble::scene::detail
