#include "core/mesh_fill.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "base/format.hpp"
#include "core/winding_tree.hpp"

namespace tumble {

namespace {

const Eigen::Vector3d& vertex(const TriangleMesh& m, int i) { return m.vertices[static_cast<std::size_t>(i)]; }

struct Crossing {
  std::size_t row;
  double x;   ///< m, where the row's line meets the triangle
  int delta;  ///< +1 entering (normal towards -x), -1 leaving
  bool operator<(const Crossing& o) const { return row != o.row ? row < o.row : x < o.x; }
};

using Vec2 = Eigen::Vector2d;

// Edge function of p against the directed edge a -> b in the (y, z) plane,
// evaluated with the endpoints in index order, so the two triangles sharing an
// edge see exactly opposite values; the top-left rule then gives a point on
// the edge to exactly one of them (rasterisers' rule, made exact).
bool inside_edge(int ia, int ib, const Vec2& a, const Vec2& b, const Vec2& p) {
  const bool swapped = ia > ib;
  const Vec2& s = swapped ? b : a;
  const Vec2& e = swapped ? a : b;
  double f = (e.x() - s.x()) * (p.y() - s.y()) - (e.y() - s.y()) * (p.x() - s.x());
  if (swapped) f = -f;
  if (f != 0) return f > 0;
  const double du = b.x() - a.x(), dv = b.y() - a.y();
  return dv < 0 || (dv == 0 && du < 0);
}

Eigen::Vector3d box_lo(const TriangleMesh& m) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY);
  for (const auto& v : m.vertices) lo = lo.cwiseMin(v);
  return lo;
}

// The mesh in the lattice's axes (a copy only when the lattice is turned).
const TriangleMesh& in_lattice_axes(const TriangleMesh& mesh, const LatticeSpec& l, TriangleMesh& turned) {
  if (l.orientation.coeffs() == Eigen::Quaterniond::Identity().coeffs()) return mesh;
  turned = mesh;
  const Eigen::Matrix3d to_lattice = l.orientation.conjugate().toRotationMatrix();
  for (auto& v : turned.vertices) v = to_lattice * v;
  return turned;
}

// Lattice points per axis over the bounding box of `mesh`, given in the lattice's axes.
Eigen::Vector3d counts_in_lattice_axes(const TriangleMesh& mesh, const LatticeSpec& l) {
  Eigen::Vector3d lo = box_lo(mesh), hi = lo;
  for (const auto& v : mesh.vertices) hi = hi.cwiseMax(v);
  Eigen::Vector3d n;
  for (int a = 0; a < 3; ++a) n[a] = std::max(0.0, std::floor((hi[a] - lo[a]) / l.spacing - l.offset[a]) + 1);
  return n;
}

Eigen::Vector3d point_at(const Eigen::Vector3d& lo, const LatticeSpec& l, double i, double j, double k) {
  return lo + l.spacing * (Eigen::Vector3d(i, j, k) + l.offset);
}

// All row crossings, sorted by row then x. Rows run along x; row = k * ny + j.
std::vector<Crossing> row_crossings(const TriangleMesh& mesh, const Eigen::Vector3d& lo, const LatticeSpec& l,
                                    long ny, long nz, double max_crossings) {
  std::vector<Crossing> out;
  const double h = l.spacing;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d &p0 = vertex(mesh, t[0]), &p1 = vertex(mesh, t[1]), &p2 = vertex(mesh, t[2]);
    const Eigen::Vector3d d = (p1 - p0).cross(p2 - p0);
    if (d.x() == 0) continue;  // edge-on to the rows: crossed by none in the limit
    // Counter-clockwise in (y, z): reverse the corners of a triangle facing -x.
    int ia = t[0], ib = t[1], ic = t[2];
    if (d.x() < 0) std::swap(ib, ic);
    const Vec2 a(vertex(mesh, ia).y(), vertex(mesh, ia).z()), b(vertex(mesh, ib).y(), vertex(mesh, ib).z()),
        c(vertex(mesh, ic).y(), vertex(mesh, ic).z());
    const double ymin = std::min({a.x(), b.x(), c.x()}), ymax = std::max({a.x(), b.x(), c.x()});
    const double zmin = std::min({a.y(), b.y(), c.y()}), zmax = std::max({a.y(), b.y(), c.y()});
    const long j0 = std::max(0L, static_cast<long>(std::ceil((ymin - lo.y()) / h - l.offset.y())));
    const long j1 = std::min(ny - 1, static_cast<long>(std::floor((ymax - lo.y()) / h - l.offset.y())));
    const long k0 = std::max(0L, static_cast<long>(std::ceil((zmin - lo.z()) / h - l.offset.z())));
    const long k1 = std::min(nz - 1, static_cast<long>(std::floor((zmax - lo.z()) / h - l.offset.z())));
    for (long k = k0; k <= k1; ++k)
      for (long j = j0; j <= j1; ++j) {
        const Eigen::Vector3d q = point_at(lo, l, 0, double(j), double(k));
        const Vec2 p(q.y(), q.z());
        if (!inside_edge(ia, ib, a, b, p) || !inside_edge(ib, ic, b, c, p) || !inside_edge(ic, ia, c, a, p)) continue;
        const double x = p0.x() - (d.y() * (q.y() - p0.y()) + d.z() * (q.z() - p0.z())) / d.x();
        out.push_back({static_cast<std::size_t>(k * ny + j), x, d.x() < 0 ? 1 : -1});
        if (static_cast<double>(out.size()) > max_crossings)
          throw FillTooCostly("the lattice rows cross the surface more than " + format_number(max_crossings, 3) +
                              " times (many layers of surface, each met by every row)");
      }
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// The tree's winding number at p, its work counted in `out` against `limits`.
double counted_winding(const WindingTree& tree, const Eigen::Vector3d& p, const FillLimits& limits, VolumeFill& out) {
  ++out.winding_evaluations;
  const double w = tree.winding_number(p, &out.winding_work);
  if (static_cast<double>(out.winding_work) > limits.max_winding_work)
    throw FillTooCostly("the winding-number test needed more than " + format_number(limits.max_winding_work, 3) +
                        " steps by lattice point " + std::to_string(out.winding_evaluations) + " of " +
                        format_number(out.lattice_points, 3) +
                        " (open surfaces stacked or lying on each other keep every point near all of them)");
  return w;
}

}  // namespace

double winding_number(const TriangleMesh& mesh, const Eigen::Vector3d& p) {
  double sum = 0;
  for (const auto& t : mesh.triangles) {
    sum += triangle_solid_angle(vertex(mesh, t[0]), vertex(mesh, t[1]), vertex(mesh, t[2]), p);
  }
  return sum / (4 * std::numbers::pi);
}

Eigen::Vector3d lattice_counts(const TriangleMesh& mesh, const LatticeSpec& l) {
  TriangleMesh turned;
  return counts_in_lattice_axes(in_lattice_axes(mesh, l, turned), l);
}

VolumeFill fill_volume(const TriangleMesh& mesh_in, bool watertight, const LatticeSpec& l, double mass,
                       const FillLimits& limits) {
  VolumeFill out;
  TriangleMesh turned;
  const TriangleMesh& mesh = in_lattice_axes(mesh_in, l, turned);
  if (mesh.triangles.empty() || !(l.spacing > 0)) return out;
  const Eigen::Vector3d lo = box_lo(mesh), n = counts_in_lattice_axes(mesh, l);
  out.lattice_points = n.prod();
  if (out.lattice_points > limits.max_points) return out;
  const long nx = long(n.x()), ny = long(n.y()), nz = long(n.z());
  const std::vector<Crossing> xs = row_crossings(mesh, lo, l, ny, nz, limits.max_crossings);
  std::vector<Eigen::Vector3d> inside;
  std::optional<WindingTree> tree;  // built only for a mesh with holes
  if (!watertight) tree.emplace(mesh);
  auto gwn = [&](long i, long j, long k) {
    return counted_winding(*tree, point_at(lo, l, double(i), double(j), double(k)), limits, out);
  };
  std::size_t c = 0;
  for (long k = 0; k < nz; ++k)
    for (long j = 0; j < ny; ++j) {
      const std::size_t row = static_cast<std::size_t>(k * ny + j);
      const std::size_t first = c;
      while (c < xs.size() && xs[c].row == row) ++c;
      const double x0 = point_at(lo, l, 0, 0, 0).x();
      if (watertight) {
        int w = 0;
        std::size_t m = first;
        for (long i = 0; i < nx; ++i) {
          const double x = x0 + l.spacing * double(i);
          while (m < c && xs[m].x < x) w += xs[m++].delta;
          if (w > 0) inside.push_back(point_at(lo, l, double(i), double(j), double(k)));
          if (w > 1 || w < 0) ++out.overlapped;
        }
        continue;
      }
      // Stretches of the row between crossings: the winding number is
      // continuous on each; trust three samples when they agree on an integer.
      long i = 0;
      for (std::size_t m = first; i < nx; ++m) {
        long end = nx;  // one past the stretch's last point
        if (m < c) end = std::clamp(long(std::ceil((xs[m].x - x0) / l.spacing)), i, nx);
        if (end == i) continue;
        const double w0 = gwn(i, j, k), w1 = gwn((i + end - 1) / 2, j, k), w2 = gwn(end - 1, j, k);
        const double r = std::round(w0);
        const bool settled = std::abs(w0 - r) < 0.1 && std::abs(w1 - r) < 0.1 && std::abs(w2 - r) < 0.1;
        for (long q = i; q < end; ++q) {
          const double w = settled ? r : gwn(q, j, k);
          if (w > 0.25) ++out.near, out.ambiguous += w < 0.75;
          if (w >= 1.5 || w <= -0.5) ++out.overlapped;
          if (w >= 0.5) inside.push_back(point_at(lo, l, double(q), double(j), double(k)));
        }
        i = end;
      }
    }
  out.cloud.reserve(inside.size());
  const double each = inside.empty() ? 0 : mass / static_cast<double>(inside.size());
  const Eigen::Matrix3d to_mesh = l.orientation.toRotationMatrix();
  for (const auto& p : inside) out.cloud.push_back({to_mesh * p, each});
  return out;
}

ParticleCloud fill_surface(const TriangleMesh& mesh, std::size_t count, double mass, std::uint64_t seed) {
  std::vector<double> cumulative;
  cumulative.reserve(mesh.triangles.size());
  double total = 0;
  for (const auto& t : mesh.triangles) {
    total += 0.5 * (vertex(mesh, t[1]) - vertex(mesh, t[0])).cross(vertex(mesh, t[2]) - vertex(mesh, t[0])).norm();
    cumulative.push_back(total);
  }
  ParticleCloud out;
  if (!(total > 0) || count == 0) return out;
  out.reserve(count);
  UnitRandom rnd(seed);
  for (std::size_t s = 0; s < count; ++s) {
    const auto it = std::upper_bound(cumulative.begin(), cumulative.end(), rnd() * total);
    const auto& t = mesh.triangles[static_cast<std::size_t>(
        std::min<std::ptrdiff_t>(it - cumulative.begin(), std::ptrdiff_t(cumulative.size()) - 1))];
    const double r1 = std::sqrt(rnd()), r2 = rnd();  // uniform on the triangle (Osada et al. 2002)
    const Eigen::Vector3d p = (1 - r1) * vertex(mesh, t[0]) + r1 * (1 - r2) * vertex(mesh, t[1]) +
                              r1 * r2 * vertex(mesh, t[2]);
    out.push_back({p, mass / static_cast<double>(count)});
  }
  return out;
}

SolidProperties shell_properties(const TriangleMesh& mesh) {
  SolidProperties out;
  if (mesh.vertices.empty()) return out;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  for (const auto& v : mesh.vertices) origin += v;
  origin /= static_cast<double>(mesh.vertices.size());
  double area = 0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();  // ∫ r rᵀ dA about `origin`
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d a = vertex(mesh, t[0]) - origin, b = vertex(mesh, t[1]) - origin,
                          c = vertex(mesh, t[2]) - origin;
    const double A = 0.5 * (b - a).cross(c - a).norm();
    const Eigen::Vector3d s = a + b + c;
    area += A;
    first += A / 3 * s;
    second += A / 12 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  out.volume = area;
  if (!(area > 0)) return out;
  const Eigen::Vector3d g = first / area;
  const Eigen::Matrix3d central = second - area * g * g.transpose();
  out.centroid = origin + g;
  out.inertia = central.trace() * Eigen::Matrix3d::Identity() - central;
  return out;
}

}  // namespace tumble
