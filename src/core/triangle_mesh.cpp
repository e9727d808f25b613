#include "core/triangle_mesh.hpp"

#include <algorithm>
#include <cstdint>
#include <tuple>

namespace tumble {

namespace {

Eigen::Vector3d corner(const TriangleMesh& m, const std::array<int, 3>& t, int k) {
  return m.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])];
}

// Eberly's per-axis subexpressions of the triangle's polynomial integrals.
struct Sub {
  double f1, f2, f3, g0, g1, g2;
};

Sub subexpressions(double w0, double w1, double w2) {
  const double t0 = w0 + w1, t1 = w0 * w0, t2 = t1 + w1 * t0;
  Sub s;
  s.f1 = t0 + w2;
  s.f2 = t2 + w2 * s.f1;
  s.f3 = w0 * t1 + w1 * t2 + w2 * s.f2;
  s.g0 = s.f2 + w0 * (s.f1 + w0);
  s.g1 = s.f2 + w1 * (s.f1 + w1);
  s.g2 = s.f2 + w2 * (s.f1 + w2);
  return s;
}

}  // namespace

MeshReport inspect_mesh(const TriangleMesh& mesh) {
  MeshReport r;
  r.triangles = mesh.triangles.size();
  r.vertices = mesh.vertices.size();
  if (!mesh.vertices.empty()) {
    r.box_min = r.box_max = mesh.vertices.front();
    for (const auto& v : mesh.vertices) {
      r.box_min = r.box_min.cwiseMin(v);
      r.box_max = r.box_max.cwiseMax(v);
    }
  }
  const double diag2 = (r.box_max - r.box_min).squaredNorm();
  // (low, high, +1 if traversed low -> high): sorted, equal pairs are one edge.
  std::vector<std::tuple<int, int, int>> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d a = corner(mesh, t, 0), b = corner(mesh, t, 1), c = corner(mesh, t, 2);
    const double area = 0.5 * (b - a).cross(c - a).norm();
    r.area += area;
    if (!(area > 1e-12 * diag2)) ++r.degenerate_faces;
    r.signed_volume += a.dot(b.cross(c)) / 6.0;
    for (int k = 0; k < 3; ++k) {
      const int u = t[static_cast<std::size_t>(k)], v = t[static_cast<std::size_t>((k + 1) % 3)];
      if (u != v) edges.emplace_back(std::min(u, v), std::max(u, v), u < v ? 1 : -1);
    }
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    int net = 0;
    while (j < edges.size() && std::get<0>(edges[j]) == std::get<0>(edges[i]) &&
           std::get<1>(edges[j]) == std::get<1>(edges[i]))
      net += std::get<2>(edges[j++]);
    const std::size_t uses = j - i;
    if (uses == 1) ++r.boundary_edges;
    else if (uses > 2) ++r.non_manifold_edges;
    else if (net != 0) ++r.misoriented_edges;
    i = j;
  }
  return r;
}

void flip_orientation(TriangleMesh& mesh) {
  for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
}

std::size_t remove_degenerate_triangles(TriangleMesh& mesh) {
  const std::size_t before = mesh.triangles.size();
  std::erase_if(mesh.triangles, [&](const std::array<int, 3>& t) {
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return true;
    const Eigen::Vector3d a = corner(mesh, t, 0);
    return (corner(mesh, t, 1) - a).cross(corner(mesh, t, 2) - a).squaredNorm() == 0.0;
  });
  return before - mesh.triangles.size();
}

SolidProperties solid_properties(const TriangleMesh& mesh) {
  SolidProperties out;
  if (mesh.vertices.empty() || mesh.triangles.empty()) return out;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  for (const auto& v : mesh.vertices) origin += v;
  origin /= static_cast<double>(mesh.vertices.size());

  // Integrals of 1, x, y, z, x², y², z², xy, yz, zx (Eberly's order).
  double in[10] = {};
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d p0 = corner(mesh, t, 0) - origin, p1 = corner(mesh, t, 1) - origin,
                          p2 = corner(mesh, t, 2) - origin;
    const Eigen::Vector3d d = (p1 - p0).cross(p2 - p0);
    const Sub x = subexpressions(p0.x(), p1.x(), p2.x());
    const Sub y = subexpressions(p0.y(), p1.y(), p2.y());
    const Sub z = subexpressions(p0.z(), p1.z(), p2.z());
    in[0] += d.x() * x.f1;
    in[1] += d.x() * x.f2;
    in[2] += d.y() * y.f2;
    in[3] += d.z() * z.f2;
    in[4] += d.x() * x.f3;
    in[5] += d.y() * y.f3;
    in[6] += d.z() * z.f3;
    in[7] += d.x() * (p0.y() * x.g0 + p1.y() * x.g1 + p2.y() * x.g2);
    in[8] += d.y() * (p0.z() * y.g0 + p1.z() * y.g1 + p2.z() * y.g2);
    in[9] += d.z() * (p0.x() * z.g0 + p1.x() * z.g1 + p2.x() * z.g2);
  }
  constexpr double kScale[10] = {1. / 6, 1. / 24, 1. / 24, 1. / 24, 1. / 60, 1. / 60, 1. / 60, 1. / 120, 1. / 120, 1. / 120};
  for (int i = 0; i < 10; ++i) in[i] *= kScale[i];

  const double V = in[0];
  out.volume = V;
  if (V == 0) return out;
  const Eigen::Vector3d c(in[1] / V, in[2] / V, in[3] / V);  // relative to `origin`
  out.centroid = origin + c;
  Eigen::Matrix3d& J = out.inertia;
  J(0, 0) = in[5] + in[6] - V * (c.y() * c.y() + c.z() * c.z());
  J(1, 1) = in[4] + in[6] - V * (c.z() * c.z() + c.x() * c.x());
  J(2, 2) = in[4] + in[5] - V * (c.x() * c.x() + c.y() * c.y());
  J(0, 1) = J(1, 0) = -(in[7] - V * c.x() * c.y());
  J(1, 2) = J(2, 1) = -(in[8] - V * c.y() * c.z());
  J(0, 2) = J(2, 0) = -(in[9] - V * c.z() * c.x());
  return out;
}

}  // namespace tumble
