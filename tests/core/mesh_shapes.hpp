// Small closed meshes with known answers, for the mesh tests.
#pragma once

#include <cmath>
#include <map>
#include <utility>

#include "core/triangle_mesh.hpp"

namespace tumble::test {

/// Axis-aligned box of full edge lengths `size` centred at `center`, outward normals.
inline TriangleMesh box_mesh(const Eigen::Vector3d& size, const Eigen::Vector3d& center = Eigen::Vector3d::Zero()) {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.push_back(center + 0.5 * size.cwiseProduct(Eigen::Vector3d(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1)));
  // Faces as quads (counter-clockwise from outside), split in two.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back({q[0], q[1], q[2]});
    m.triangles.push_back({q[0], q[2], q[3]});
  }
  return m;
}

/// Tetrahedron with corners a, b, c, d, oriented outwards whatever their order.
inline TriangleMesh tetra_mesh(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                               const Eigen::Vector3d& d) {
  TriangleMesh m{{a, b, c, d}, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
  if ((b - a).cross(c - a).dot(d - a) < 0) flip_orientation(m);
  return m;
}

/// Icosahedron subdivided `level` times, vertices pushed onto the sphere of `radius`.
inline TriangleMesh icosphere(int level, double radius) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  TriangleMesh m;
  for (const auto& v : {Eigen::Vector3d(-1, t, 0), Eigen::Vector3d(1, t, 0), Eigen::Vector3d(-1, -t, 0),
                        Eigen::Vector3d(1, -t, 0), Eigen::Vector3d(0, -1, t), Eigen::Vector3d(0, 1, t),
                        Eigen::Vector3d(0, -1, -t), Eigen::Vector3d(0, 1, -t), Eigen::Vector3d(t, 0, -1),
                        Eigen::Vector3d(t, 0, 1), Eigen::Vector3d(-t, 0, -1), Eigen::Vector3d(-t, 0, 1)})
    m.vertices.push_back(v.normalized() * radius);
  m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int l = 0; l < level; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      if (auto it = mid.find(key); it != mid.end()) return it->second;
      m.vertices.push_back((m.vertices[std::size_t(a)] + m.vertices[std::size_t(b)]).normalized() * radius);
      return mid[key] = int(m.vertices.size()) - 1;
    };
    std::vector<std::array<int, 3>> next;
    for (const auto& f : m.triangles) {
      const int a = midpoint(f[0], f[1]), b = midpoint(f[1], f[2]), c = midpoint(f[2], f[0]);
      next.insert(next.end(), {{f[0], a, c}, {f[1], b, a}, {f[2], c, b}, {a, b, c}});
    }
    m.triangles = std::move(next);
  }
  return m;
}

/// A lumpy, non-convex but star-shaped closed mesh (an icosphere with a wavy radius).
inline TriangleMesh lumpy_mesh(int level) {
  TriangleMesh m = icosphere(level, 1.0);
  for (auto& v : m.vertices) v *= 1.0 + 0.35 * std::sin(3 * v.x()) * std::cos(4 * v.y() + v.z());
  return m;
}

}  // namespace tumble::test
