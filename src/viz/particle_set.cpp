#include "viz/particle_set.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace tumble::viz {
namespace {

// Integer cell coordinates packed into one key; 21 bits per axis.
using Key = std::int64_t;
constexpr Key kBits = 21;
Key pack(const glm::i64vec3& c) { return (c.z << (2 * kBits)) | (c.y << kBits) | c.x; }

struct Grid {
  glm::dvec3 lo;
  glm::dvec3 cell;
  glm::i64vec3 n;  // cells per axis
  glm::i64vec3 of(const glm::dvec3& p) const {
    return glm::clamp(glm::i64vec3(glm::floor((p - lo) / cell)), glm::i64vec3(0), n - glm::i64vec3(1));
  }
  bool inside(const glm::i64vec3& c) const { return glm::all(glm::greaterThanEqual(c, glm::i64vec3(0))) && glm::all(glm::lessThan(c, n)); }
};

Grid make_grid(const std::vector<glm::dvec3>& positions, const ShellGrid& sg) {
  glm::dvec3 hi = sg.lo;
  for (const auto& p : positions) hi = glm::max(hi, p);
  const glm::i64vec3 n = glm::i64vec3(glm::floor((hi - sg.lo) / sg.cell)) + glm::i64vec3(1);
  return {sg.lo, sg.cell, glm::min(n, glm::i64vec3((Key(1) << kBits) - 1))};
}

glm::i64vec3::value_type largest(const glm::i64vec3& v) { return std::max({v.x, v.y, v.z}); }

std::vector<glm::dvec3> positions_of(const ParticleCloud& cloud) {
  std::vector<glm::dvec3> out;
  out.reserve(cloud.size());
  for (const Particle& p : cloud) out.emplace_back(p.position.x(), p.position.y(), p.position.z());
  return out;
}

// Mean position and colour of the members of each occupied cell.
void merge_cells(const Grid& g, std::vector<glm::dvec3>& positions, std::vector<Color>& colors) {
  std::unordered_map<Key, std::size_t> slot;
  std::vector<glm::dvec3> sum_p;
  std::vector<glm::dvec4> sum_c;
  std::vector<double> count;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const auto [it, fresh] = slot.try_emplace(pack(g.of(positions[i])), sum_p.size());
    if (fresh) sum_p.emplace_back(0), sum_c.emplace_back(0), count.push_back(0);
    sum_p[it->second] += positions[i];
    sum_c[it->second] += glm::dvec4(colors[i]);
    count[it->second] += 1;
  }
  positions.resize(sum_p.size());
  colors.resize(sum_p.size());
  for (std::size_t k = 0; k < sum_p.size(); ++k) {
    positions[k] = sum_p[k] / count[k];
    colors[k] = Color(sum_c[k] / count[k]);
  }
}

ParticleLevel shell_level(const std::vector<glm::dvec3>& positions, const std::vector<Color>& colors,
                          const ShellGrid& grid, float radius) {
  const std::vector<std::uint8_t> exposed = exposed_directions(positions, grid);
  ParticleLevel level;
  level.radius = radius;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (!exposed[i]) continue;
    level.positions.emplace_back(positions[i]);
    level.colors.push_back(colors[i]);
    level.exposed.push_back(exposed[i]);
  }
  return level;
}

}  // namespace

ShellGrid shell_grid(const std::vector<glm::dvec3>& positions) {
  if (positions.empty()) return {};
  glm::dvec3 lo = positions.front(), hi = lo;
  for (const auto& p : positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const glm::dvec3 span = hi - lo;
  const double widest = std::max({span.x, span.y, span.z, 1e-300});
  // Distinct coordinates per axis (to a billionth of the body's size).
  glm::dvec3 distinct;
  for (int a = 0; a < 3; ++a) {
    std::vector<double> v;
    v.reserve(positions.size());
    for (const auto& p : positions) v.push_back(std::round((p[a] - lo[a]) / widest * 1e9));
    std::sort(v.begin(), v.end());
    distinct[a] = double(std::unique(v.begin(), v.end()) - v.begin());
  }
  const double n = static_cast<double>(positions.size());
  if (distinct.x * distinct.y * distinct.z <= 64 * n) {
    glm::dvec3 cell;
    for (int a = 0; a < 3; ++a) cell[a] = distinct[a] > 1 ? span[a] / (distinct[a] - 1) * (1 + 1e-6) : widest;
    return {lo - 0.5 * cell, cell};
  }
  const glm::dvec3 ext = glm::max(span, glm::dvec3(1e-12 * widest));
  // The spacing of a box-filling lattice of n points (cells of n^(1/3) per
  // axis span the extent plus one spacing), widened a little.
  const double s = std::cbrt(ext.x * ext.y * ext.z / n);
  const double cell = 1.05 * std::cbrt((ext.x + s) * (ext.y + s) * (ext.z + s) / n);
  return {lo, glm::dvec3(cell)};
}

std::vector<std::uint8_t> exposed_directions(const std::vector<glm::dvec3>& positions, const ShellGrid& grid) {
  std::vector<std::uint8_t> out(positions.size(), 0);
  if (positions.empty()) return out;
  const Grid g = make_grid(positions, grid);
  std::unordered_map<Key, std::uint8_t> mask;  // occupied cell -> its own empty directions
  mask.reserve(positions.size());
  for (const auto& p : positions) mask.emplace(pack(g.of(p)), 0);
  auto occupied = [&](const glm::i64vec3& c) { return g.inside(c) && mask.count(pack(c)); };
  for (auto& [key, m] : mask) {
    const glm::i64vec3 c(key & ((Key(1) << kBits) - 1), (key >> kBits) & ((Key(1) << kBits) - 1), key >> (2 * kBits));
    for (int a = 0; a < 3; ++a)
      for (int s = 0; s < 2; ++s) {
        glm::i64vec3 nb = c;
        nb[a] += s ? -1 : 1;
        if (!occupied(nb)) m |= std::uint8_t(1u << (2 * a + s));
      }
  }
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const glm::i64vec3 c = g.of(positions[i]);
    if (!mask.at(pack(c))) continue;  // interior
    std::uint8_t m = 0;
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const glm::i64vec3 nb = c + glm::i64vec3(dx, dy, dz);
          if (!g.inside(nb)) continue;
          const auto it = mask.find(pack(nb));
          if (it != mask.end()) m |= it->second;
        }
    out[i] = m;
  }
  return out;
}

bool faces_eye(std::uint8_t exposed, const glm::vec3& p, const glm::vec3& eye, float radius) {
  const glm::vec3 d = eye - p;
  for (int a = 0; a < 3; ++a) {
    if ((exposed & (1u << (2 * a))) && d[a] > -radius) return true;
    if ((exposed & (1u << (2 * a + 1))) && -d[a] > -radius) return true;
  }
  return false;
}

void facing_particles(const ParticleLevel& level, const glm::dmat4& model, const Camera& camera,
                      std::vector<std::uint32_t>& out) {
  glm::dvec3 eye = camera.position;
  if (camera.ortho_half_height > 0) eye = camera.target + 1e6 * glm::normalize(camera.position - camera.target);
  const glm::vec3 eye_cloud(glm::inverse(model) * glm::dvec4(eye, 1.0));
  out.clear();
  for (std::uint32_t i = 0; i < level.positions.size(); ++i)
    if (faces_eye(level.exposed[i], level.positions[i], eye_cloud, level.radius)) out.push_back(i);
}

std::shared_ptr<const ParticleSet> make_particle_set(const ParticleCloud& cloud, const std::vector<Color>& colors,
                                                     float radius) {
  auto set = std::make_shared<ParticleSet>();
  std::vector<glm::dvec3> positions = positions_of(cloud);
  if (positions.empty()) return set;
  std::vector<Color> c = colors;
  c.resize(positions.size(), Color(0.5f, 0.5f, 0.5f, 1.0f));
  glm::dvec3 lo = positions.front(), hi = lo;
  for (const auto& p : positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  set->center = glm::vec3(0.5 * (lo + hi));
  set->bound_radius = static_cast<float>(0.5 * glm::length(hi - lo)) + radius;
  ShellGrid grid = shell_grid(positions);
  set->levels.push_back(shell_level(positions, c, grid, radius));
  for (int level = 1;; ++level) {
    grid.cell *= 2.0;
    const Grid g = make_grid(positions, grid);
    if (largest(g.n) < 4) break;  // too coarse to show the shape
    merge_cells(g, positions, c);
    if (positions.size() < kMinLevelParticles) break;
    set->levels.push_back(shell_level(positions, c, grid, radius * static_cast<float>(1 << level)));
  }
  return set;
}

std::size_t particle_level(const ParticleSet& set, const glm::dmat4& model, const Camera& camera,
                           double viewport_height_px) {
  if (set.levels.empty()) return 0;
  double px_per_m_at_unit_depth = 0;  // pixels per metre, times the depth for perspective
  double depth = 1;
  if (camera.ortho_half_height > 0) {
    px_per_m_at_unit_depth = 0.5 * viewport_height_px / camera.ortho_half_height;
  } else {
    const glm::dvec3 c = glm::dvec3(model * glm::dvec4(glm::dvec3(set.center), 1.0));
    depth = glm::length(c - camera.position) - set.bound_radius;
    if (!(depth > camera.near_m)) return 0;  // the eye is in or at the body: finest
    px_per_m_at_unit_depth = 0.5 * viewport_height_px / std::tan(0.5 * glm::radians(camera.fov_y_deg));
  }
  for (std::size_t l = 0; l < set.levels.size(); ++l)
    if (set.levels[l].radius * px_per_m_at_unit_depth / depth >= kMinParticleRadiusPx) return l;
  return set.levels.size() - 1;
}

}  // namespace tumble::viz
