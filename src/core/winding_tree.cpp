#include "core/winding_tree.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tumble {

namespace {
constexpr int kLeafSize = 8;  // triangles summed exactly per leaf
}

double triangle_solid_angle(const Eigen::Vector3d& a0, const Eigen::Vector3d& b0, const Eigen::Vector3d& c0,
                            const Eigen::Vector3d& p) {
  const Eigen::Vector3d a = a0 - p, b = b0 - p, c = c0 - p;
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double num = a.dot(b.cross(c));
  const double den = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
  return 2 * std::atan2(num, den);
}

WindingTree::WindingTree(const TriangleMesh& mesh, double beta) : beta_(beta) {
  tris_.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    tris_.push_back({mesh.vertices[std::size_t(t[0])], mesh.vertices[std::size_t(t[1])],
                     mesh.vertices[std::size_t(t[2])]});
  nodes_.reserve(2 * tris_.size() / kLeafSize + 1);
  if (!tris_.empty()) build(0, int(tris_.size()));
}

// Median split of the triangles' centroids along the longest axis of their box.
int WindingTree::build(int first, int count) {
  const auto begin = tris_.begin() + first, end = begin + count;
  auto centroid = [](const std::array<Eigen::Vector3d, 3>& t) { return (t[0] + t[1] + t[2]) / 3; };
  Node n;
  n.first = first;
  n.count = count;
  n.dipole.setZero();
  n.quad.setZero();
  double area = 0;
  Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  for (auto it = begin; it != end; ++it) {
    const Eigen::Vector3d twice_area_normal = ((*it)[1] - (*it)[0]).cross((*it)[2] - (*it)[0]);
    const double a = 0.5 * twice_area_normal.norm();
    const Eigen::Vector3d c = centroid(*it);
    n.dipole += 0.5 * twice_area_normal;
    area += a;
    weighted += a * c;
    lo = lo.cwiseMin(c);
    hi = hi.cwiseMax(c);
  }
  // A node of zero area (degenerate triangles) expands about its box centre.
  n.center = area > 0 ? Eigen::Vector3d(weighted / area) : Eigen::Vector3d(0.5 * (lo + hi));
  double r2 = 0;
  for (auto it = begin; it != end; ++it) {
    const Eigen::Vector3d area_normal = 0.5 * ((*it)[1] - (*it)[0]).cross((*it)[2] - (*it)[0]);
    n.quad += (centroid(*it) - n.center) * area_normal.transpose();
    for (const auto& v : *it) r2 = std::max(r2, (v - n.center).squaredNorm());
  }
  n.radius2 = beta_ * beta_ * r2;
  const int index = int(nodes_.size());
  nodes_.push_back(n);
  if (count <= kLeafSize) return index;
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  const auto mid = begin + count / 2;
  std::nth_element(begin, mid, end, [&](const auto& s, const auto& t) {
    return s[0][axis] + s[1][axis] + s[2][axis] < t[0][axis] + t[1][axis] + t[2][axis];
  });
  const int left = build(first, count / 2);
  const int right = build(first + count / 2, count - count / 2);
  nodes_[std::size_t(index)].left = left;
  nodes_[std::size_t(index)].right = right;
  return index;
}

double WindingTree::winding_number(const Eigen::Vector3d& p, std::size_t* work) const {
  if (nodes_.empty()) return 0;
  double sum = 0;  // 4π × winding number
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  std::size_t visited = 0;
  while (top > 0) {
    const Node& n = nodes_[std::size_t(stack[--top])];
    ++visited;
    const Eigen::Vector3d r = n.center - p;
    const double d2 = r.squaredNorm();
    if (d2 > n.radius2) {
      // Far: the solid angle of an area element dA n at x is dA n·(x − p)/|x − p|³;
      // Taylor-expand (x − p)/|x − p|³ about the centre to first order in x − centre.
      const double inv2 = 1 / d2, inv3 = inv2 / std::sqrt(d2);
      sum += inv3 * (n.dipole.dot(r) + n.quad.trace() - 3 * inv2 * r.dot(n.quad * r));
    } else if (n.left < 0) {
      visited += std::size_t(n.count);
      for (int t = n.first; t < n.first + n.count; ++t) {
        const auto& tri = tris_[std::size_t(t)];
        sum += triangle_solid_angle(tri[0], tri[1], tri[2], p);
      }
    } else {
      stack[top++] = n.left;
      stack[top++] = n.right;
    }
  }
  if (work) *work += visited;
  return sum / (4 * std::numbers::pi);
}

}  // namespace tumble
