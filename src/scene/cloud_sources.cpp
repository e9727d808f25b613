// Particle sources of a body: inline particles, a generated shape, a cloud file.
#include <algorithm>
#include <cmath>

#include "base/error.hpp"
#include "base/format.hpp"
#include "base/input_file.hpp"
#include "io/cloud_file.hpp"
#include "scene/internal.hpp"

namespace tumble::scene::detail {

namespace {

bool reserve(LoadContext& ctx, TableReader& r, std::string_view key, double n) { return reserve_particles(ctx, r, key, n); }

}  // namespace

bool reserve_particles(LoadContext& ctx, TableReader& r, std::string_view key, double n) {
  if (static_cast<double>(ctx.particles) + n > static_cast<double>(kMaxParticles)) {
    r.error(key, "the scene would have more than " + std::to_string(kMaxParticles) +
                     " particles (the cap); lower the resolution");
    return false;
  }
  ctx.particles += static_cast<std::size_t>(n);
  return true;
}

namespace {

void read_particles(TableReader& r, LoadContext& ctx, const Eigen::Vector3d& offset, ParticleCloud& out) {
  const toml::node* n = r.node("particles");
  const toml::array* a = n->as_array();
  if (!a) {
    r.error("particles", "expected an array of [x, y, z, m] arrays, found " + describe(*n));
    return;
  }
  if (!reserve(ctx, r, "particles", static_cast<double>(a->size()))) return;
  ParticleCloud cloud;
  cloud.reserve(a->size());
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::node& e = *a->get(i);
    const std::string key = r.key_path("particles") + "[" + std::to_string(i) + "]";
    const toml::array* p = e.as_array();
    if (!p || p->size() != 4) {
      r.diag().error(e.source(), key, "expected [x, y, z, m] (m, m, m, kg), found " + describe(e));
      continue;
    }
    Particle part{};
    bool ok = true;
    for (int k = 0; k < 3; ++k) {
      auto x = read_number(*p->get(static_cast<std::size_t>(k)), key + "[" + std::to_string(k) + "]",
                           Range::any(), r.diag());
      if (x) part.position[k] = *x;
      else ok = false;
    }
    Range mass_range = Range::positive();
    mass_range.what = "a mass (kg) > 0";
    auto m = read_number(*p->get(3), key + "[3]", mass_range, r.diag());
    if (m && ok) {
      part.mass = *m;
      cloud.push_back(part);
    }
  }
  append_cloud(out, cloud, offset);
}

std::optional<double> mass_of(TableReader& s) {
  if (!s.has("mass")) return 1.0;
  return s.number("mass", Range::positive());
}

// A shape table's fields, each read once: a missing or bad one clears `ok`
// (its error already given) and yields a harmless stand-in.
struct ShapeFields {
  const std::string& type;
  TableReader& s;
  bool& ok;
  double require(std::string_view key, const Range& range) {
    if (!s.has(key)) {
      s.error(key, "missing; a " + type + " needs '" + std::string(key) + "' (" + range.what + ")");
      ok = false;
      return 0.0;
    }
    auto v = s.number(key, range);
    if (!v) ok = false;
    return v.value_or(0.0);
  }
  Eigen::Vector3d require_vec(std::string_view key) {
    if (!s.has(key)) {
      s.error(key, "missing; a " + type + " needs '" + std::string(key) + "' ([x, y, z], m, each > 0)");
      ok = false;
      return Eigen::Vector3d(1, 1, 1);
    }
    auto v = s.vec3(key, Range::positive());
    if (!v) ok = false;
    return v.value_or(Eigen::Vector3d(1, 1, 1));
  }
  long long resolution(long long def, long long lo, long long hi) {
    if (!s.has("resolution")) return def;
    auto v = s.integer("resolution", lo, hi);
    if (!v) ok = false;
    return v.value_or(def);
  }
};

// A box's resolution: one count for every axis, or [nx, ny, nz].
Eigen::Vector3i box_resolution(ShapeFields& f) {
  Eigen::Vector3i n(10, 10, 10);
  const toml::node* rn = f.s.node("resolution");
  if (!rn || !rn->is_array()) {
    n.setConstant(static_cast<int>(f.resolution(10, 1, 100000)));
    return n;
  }
  const toml::array& a = *rn->as_array();
  bool good = a.size() == 3;
  for (std::size_t k = 0; good && k < 3; ++k) {
    auto i = a.get(k)->as_integer();
    good = i && i->get() >= 1 && i->get() <= 100000;
    if (good) n[static_cast<int>(k)] = static_cast<int>(i->get());
  }
  if (!good) {
    f.s.error("resolution", "expected an integer or [nx, ny, nz], each in [1, 100000], found " + describe(*rn));
    f.ok = false;
  }
  return n;
}

ParticleCloud box_shape(ShapeFields& f, LoadContext& ctx, double mass, SolidShape& solid) {
  const Eigen::Vector3d size = f.require_vec("size");
  solid = {SolidShape::Kind::box, size};
  const Eigen::Vector3i n = box_resolution(f);
  if (!f.ok || !reserve(ctx, f.s, "resolution", double(n.x()) * n.y() * n.z())) return {};
  return make_box(size, n, mass);
}

ParticleCloud ellipsoid_shape(ShapeFields& f, LoadContext& ctx, double mass, SolidShape& solid) {
  const Eigen::Vector3d semi = f.require_vec("semi_axes");
  solid = {SolidShape::Kind::ellipsoid, semi};
  const int n = static_cast<int>(f.resolution(15, 2, 1000));
  if (!f.ok || !reserve(ctx, f.s, "resolution", 0.5236 * n * n * n)) return {};
  return make_ellipsoid(semi, n, mass);
}

ParticleCloud cylinder_shape(ShapeFields& f, LoadContext& ctx, double mass, SolidShape& solid) {
  const double radius = f.require("radius", Range::positive());
  const double length = f.require("length", Range::positive());
  solid = {SolidShape::Kind::cylinder, {radius, radius, length}};
  const int n = static_cast<int>(f.resolution(15, 2, 10000));
  if (!f.ok) return {};
  const double nz = std::max(1.0, std::round(n * length / (2 * radius)));
  // Cubic cells: the layers follow length / diameter, at least twice it (resolution 2).
  if (const double least = std::round(length / radius); !(least <= static_cast<double>(kMaxParticles))) {
    f.s.error("length", "length / diameter = " + format_number(length / (2 * radius), 3) + " needs at least " +
                            format_number(least, 3) + " layers of particles at any resolution (the cells are "
                            "cubes), over the cap of " + std::to_string(kMaxParticles) +
                            "; give the cylinder a thicker radius");
    return {};
  }
  if (!reserve(ctx, f.s, "resolution", 0.7854 * n * n * nz)) return {};
  return make_cylinder(radius, length, n, mass);
}

ParticleCloud t_handle_shape(ShapeFields& f, LoadContext& ctx, double mass, SolidShape& solid) {
  const double handle = f.require("handle_length", Range::positive());
  const double stem = f.require("stem_length", Range::positive());
  const double thick = f.require("thickness", Range::positive());
  solid = {SolidShape::Kind::t_handle, {handle, stem, thick}};
  if (!f.s.has("resolution")) {
    f.s.error("resolution", "missing; a t_handle needs 'resolution' (particles per metre, an integer >= 1)");
    f.ok = false;
  }
  const long long per_m = f.resolution(1, 1, 1000000);
  if (!f.ok) return {};
  auto count = [&](double len) { return std::max(1.0, std::round(len * static_cast<double>(per_m))); };
  const double nt = count(thick);
  if (!reserve(ctx, f.s, "resolution", nt * nt * (count(handle) + count(stem)))) return {};
  return make_t_handle(handle, stem, thick, static_cast<int>(per_m), mass);
}

ParticleCloud make_shape(const std::string& type, TableReader& s, LoadContext& ctx, bool& ok, SolidShape& solid) {
  ShapeFields f{type, s, ok};
  const std::optional<double> mass_read = mass_of(s);
  if (!mass_read) ok = false;
  const double mass = mass_read.value_or(1.0);  // used only when ok
  if (type == "box") return box_shape(f, ctx, mass, solid);
  if (type == "ellipsoid") return ellipsoid_shape(f, ctx, mass, solid);
  if (type == "cylinder") return cylinder_shape(f, ctx, mass, solid);
  return t_handle_shape(f, ctx, mass, solid);
}

void read_shape(TableReader& r, LoadContext& ctx, const Eigen::Vector3d& offset, ParticleCloud& out) {
  const toml::table* t = r.subtable("shape");
  if (!t) return;
  const std::string path = r.key_path("shape");
  const toml::node* tn = t->get("type");
  const toml::value<std::string>* ts = tn ? tn->as_string() : nullptr;
  const std::string type = ts ? ts->get() : "";
  if (type == "mesh") return read_mesh_shape(*t, path, ctx, offset, out);
  static constexpr std::string_view kTypes[] = {"box", "ellipsoid", "cylinder", "t_handle", "mesh"};
  if (std::find(std::begin(kTypes), std::end(kTypes), type) == std::end(kTypes)) {
    std::string msg = "expected type = \"box\", \"ellipsoid\", \"cylinder\", \"t_handle\" or \"mesh\", found ";
    msg += tn ? describe(*tn) : "no type";
    const std::string hint = closest(type, {std::begin(kTypes), std::end(kTypes)});
    if (!type.empty() && !hint.empty()) msg += "; did you mean \"" + hint + "\"?";
    ctx.diag.error(tn ? tn->source() : t->source(), path + ".type", msg);
    return;
  }
  using Keys = std::vector<std::string_view>;
  const Keys keys = type == "box"         ? Keys{"type", "size", "resolution", "mass"}
                    : type == "ellipsoid" ? Keys{"type", "semi_axes", "resolution", "mass"}
                    : type == "cylinder"  ? Keys{"type", "radius", "length", "resolution", "mass"}
                                          : Keys{"type", "handle_length", "stem_length", "thickness", "resolution", "mass"};
  TableReader s(*t, path, ctx.diag, keys);
  bool ok = true;
  try {
    SolidShape solid;
    const ParticleCloud c = make_shape(type, s, ctx, ok, solid);
    if (ok) append_cloud(out, c, offset);
    solid.offset = offset;
    if (ok && ctx.shapes) ctx.shapes->push_back({solid});
  } catch (const InputError& e) {  // generator checks we did not anticipate
    ctx.diag.error(t->source(), path, e.what());
  }
}

void read_cloud_file_source(TableReader& r, LoadContext& ctx, const Eigen::Vector3d& offset, ParticleCloud& out) {
  auto file = r.string("cloud");
  if (!file) return;
  const std::filesystem::path p = ctx.base_dir / *file;
  std::error_code ec;
  if (!std::filesystem::exists(p, ec) && !ec) {
    r.error("cloud", "expected a cloud file (x y z m per line) relative to the scene, found no file at '" +
                         p.string() + "'");
    return;
  }
  try {
    // ~10 bytes per particle at least: a larger file cannot fit the cap.
    const ParticleCloud c = io::read_cloud_file(p, 64 * kMaxParticles);
    if (reserve(ctx, r, "cloud", static_cast<double>(c.size()))) append_cloud(out, c, offset);
  } catch (const InputError& e) {
    r.error("cloud", e.what());
  } catch (const UnreadableFile& e) {  // directory, FIFO, device, permission: an I/O error, exit 1
    throw UnreadableFile(ctx.diag.located(r.node("cloud")->source(), r.key_path("cloud"), e.what()));
  }
}

}  // namespace

int read_cloud_sources(TableReader& r, LoadContext& ctx, const Eigen::Vector3d& offset, ParticleCloud& out) {
  int sources = 0;
  if (r.has("particles")) ++sources, read_particles(r, ctx, offset, out);
  if (r.has("shape")) ++sources, read_shape(r, ctx, offset, out);
  if (r.has("cloud")) ++sources, read_cloud_file_source(r, ctx, offset, out);
  return sources;
}

}  // namespace tumble::scene::detail
