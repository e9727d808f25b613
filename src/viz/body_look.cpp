#include "viz/body_look.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_set>

namespace tumble::viz {

std::vector<std::uint32_t> visible_particles(const ParticleCloud& cloud) {
  std::vector<std::uint32_t> out;
  if (cloud.size() < 64) {  // too few to hide anything
    for (std::uint32_t i = 0; i < cloud.size(); ++i) out.push_back(i);
    return out;
  }
  Eigen::Vector3d lo = cloud.front().position, hi = lo;
  for (const Particle& p : cloud) lo = lo.cwiseMin(p.position), hi = hi.cwiseMax(p.position);
  // Spacing estimate from the bounding box: at least the lattice spacing of a
  // box-filling lattice (whose points span (n - 1) spacings: hence 1.1), more
  // for other shapes (a thicker shell, still correct).
  const Eigen::Vector3d ext = (hi - lo).cwiseMax(1e-12 * (hi - lo).maxCoeff() + 1e-300);
  const double cell = 1.1 * std::cbrt(ext.prod() / static_cast<double>(cloud.size()));
  const Eigen::Vector3d n = (ext / cell).array().floor() + 1;
  auto key = [&](const Eigen::Vector3d& p) {
    const Eigen::Vector3d c = ((p - lo) / cell).array().floor();
    return static_cast<std::int64_t>((c.z() * n.y() + c.y()) * n.x() + c.x());
  };
  std::unordered_set<std::int64_t> occupied;
  occupied.reserve(cloud.size());
  for (const Particle& p : cloud) occupied.insert(key(p.position));
  const std::int64_t nx = static_cast<std::int64_t>(n.x()), nxy = nx * static_cast<std::int64_t>(n.y());
  const std::int64_t steps[6] = {1, -1, nx, -nx, nxy, -nxy};
  for (std::uint32_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3d c = ((cloud[i].position - lo) / cell).array().floor();
    const bool edge = (c.array() == 0).any() || (c.array() + 1 >= n.array()).any();
    const std::int64_t k = key(cloud[i].position);
    if (edge || std::any_of(std::begin(steps), std::end(steps), [&](std::int64_t s) { return !occupied.count(k + s); }))
      out.push_back(i);
  }
  return out;
}

std::shared_ptr<const SurfaceMesh> make_surface(const TriangleMesh& mesh) {
  auto s = std::make_shared<SurfaceMesh>();
  s->positions.reserve(3 * mesh.triangles.size());
  s->normals.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d a = mesh.vertices[std::size_t(t[0])], b = mesh.vertices[std::size_t(t[1])],
                          c = mesh.vertices[std::size_t(t[2])];
    const Eigen::Vector3d nrm = (b - a).cross(c - a).normalized();
    for (const Eigen::Vector3d& p : {a, b, c}) {
      s->positions.emplace_back(float(p.x()), float(p.y()), float(p.z()));
      s->normals.emplace_back(float(nrm.x()), float(nrm.y()), float(nrm.z()));
    }
  }
  return s;
}

}  // namespace tumble::viz
