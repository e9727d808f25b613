#include <cmath>
#include <numbers>

#include "viz/body_look.hpp"

namespace tumble::viz {

namespace {

constexpr double kPi = std::numbers::pi;

struct Builder {
  const SolidShape& s;
  SurfaceMesh& m;
  // One corner: position and normal in shape axes, placed into cloud axes.
  void vertex(const Eigen::Vector3d& p, const Eigen::Vector3d& n) {
    const Eigen::Vector3d q = s.rotation * p + s.offset, nn = (s.rotation * n).normalized();
    m.positions.emplace_back(float(q.x()), float(q.y()), float(q.z()));
    m.normals.emplace_back(float(nn.x()), float(nn.y()), float(nn.z()));
  }
  void flat(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    const Eigen::Vector3d n = (b - a).cross(c - a);
    for (const Eigen::Vector3d* p : {&a, &b, &c}) vertex(*p, n);
  }
  // The box of full edges `size` centred at `c`: two counter-clockwise triangles a face.
  void box(const Eigen::Vector3d& c, const Eigen::Vector3d& size) {
    const Eigen::Vector3d h = 0.5 * size;
    auto corner = [&](int i) { return Eigen::Vector3d(c + h.cwiseProduct(Eigen::Vector3d(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1))); };
    static const int kFaces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (const auto& f : kFaces) {
      flat(corner(f[0]), corner(f[1]), corner(f[2]));
      flat(corner(f[0]), corner(f[2]), corner(f[3]));
    }
  }
  void ellipsoid(const Eigen::Vector3d& semi) {
    constexpr int kLat = 32, kLon = 64;
    auto at = [&](int i, int j) {
      const double th = kPi * i / kLat, ph = 2 * kPi * j / kLon;
      return Eigen::Vector3d(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
    };
    // Normal of {x : Σ x_i²/a_i² = 1} at x = a ⊙ u is u ⊘ a.
    auto put = [&](const Eigen::Vector3d& u) { vertex(semi.cwiseProduct(u), u.cwiseQuotient(semi)); };
    for (int i = 0; i < kLat; ++i)
      for (int j = 0; j < kLon; ++j) {
        if (i > 0) put(at(i, j)), put(at(i + 1, j)), put(at(i, j + 1));
        if (i + 1 < kLat) put(at(i, j + 1)), put(at(i + 1, j)), put(at(i + 1, j + 1));
      }
  }
  void cylinder(double r, double len) {
    constexpr int kSides = 64;
    const double z = 0.5 * len;
    for (int j = 0; j < kSides; ++j) {
      const double a0 = 2 * kPi * j / kSides, a1 = 2 * kPi * (j + 1) / kSides;
      const Eigen::Vector3d u0(std::cos(a0), std::sin(a0), 0), u1(std::cos(a1), std::sin(a1), 0);
      const Eigen::Vector3d lo0 = r * u0 - Eigen::Vector3d(0, 0, z), lo1 = r * u1 - Eigen::Vector3d(0, 0, z);
      const Eigen::Vector3d hi0 = r * u0 + Eigen::Vector3d(0, 0, z), hi1 = r * u1 + Eigen::Vector3d(0, 0, z);
      vertex(lo0, u0), vertex(lo1, u1), vertex(hi1, u1);  // the side, smooth
      vertex(lo0, u0), vertex(hi1, u1), vertex(hi0, u0);
      flat(Eigen::Vector3d(0, 0, z), hi0, hi1);  // the caps, flat
      flat(Eigen::Vector3d(0, 0, -z), lo1, lo0);
    }
  }
};

}  // namespace

std::shared_ptr<const SurfaceMesh> solid_surface(const SolidShape& s) {
  auto m = std::make_shared<SurfaceMesh>();
  Builder b{s, *m};
  switch (s.kind) {
    case SolidShape::Kind::box: b.box(Eigen::Vector3d::Zero(), s.size); break;
    case SolidShape::Kind::ellipsoid: b.ellipsoid(s.size); break;
    case SolidShape::Kind::cylinder: b.cylinder(s.size.x(), s.size.z()); break;
    case SolidShape::Kind::t_handle: {
      // As make_t_handle builds it: the handle along x, the stem along +y from
      // the handle's edge, the whole centred on its bounding box.
      const double h = s.size.x(), st = s.size.y(), t = s.size.z();
      b.box({0, -0.5 * st, 0}, {h, t, t});
      b.box({0, 0.5 * t, 0}, {t, st, t});
      break;
    }
  }
  return m;
}

}  // namespace tumble::viz
