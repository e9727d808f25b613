#include "viz/body_look.hpp"

#include "viz/particle_set.hpp"

namespace tumble::viz {

std::vector<std::uint32_t> visible_particles(const ParticleCloud& cloud) {
  std::vector<glm::dvec3> positions;
  for (const Particle& p : cloud) positions.emplace_back(p.position.x(), p.position.y(), p.position.z());
  const std::vector<std::uint8_t> exposed = exposed_directions(positions, shell_grid(positions));
  std::vector<std::uint32_t> out;
  for (std::uint32_t i = 0; i < exposed.size(); ++i)
    if (exposed[i] || cloud.size() < 64) out.push_back(i);  // a few particles hide nothing
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

std::pair<Eigen::Vector3d, Eigen::Vector3d> principal_extent(const std::vector<std::shared_ptr<const SurfaceMesh>>& surfaces,
                                                             const Eigen::Matrix3d& axes, const Eigen::Vector3d& com) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = Eigen::Vector3d::Constant(-1e300);
  for (const auto& s : surfaces)
    for (const glm::vec3& p : s->positions) {
      const Eigen::Vector3d q = axes.transpose() * (Eigen::Vector3d(p.x, p.y, p.z) - com);
      lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
    }
  if (!(hi.x() >= lo.x())) return {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  return {0.5 * (lo + hi), 0.5 * (hi - lo)};
}

}  // namespace tumble::viz
