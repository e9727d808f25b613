#include "viz/momentum_sphere.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "viz/scene_view.hpp"

namespace tumble::viz {

namespace {

constexpr double kPi = std::numbers::pi;

glm::dvec3 g(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

// Around axis `a` (0 or 2): the other two components on an ellipse, Π_a from the sphere.
std::vector<std::vector<Eigen::Vector3d>> around(int a, const Eigen::Vector3d& I, double L, double two_E, int n) {
  const int b = a == 0 ? 1 : 0, c = a == 0 ? 2 : 1;
  // Eliminating Π_a: Π_b²(1/I_b - 1/I_a) + Π_c²(1/I_c - 1/I_a) = 2E - L²/I_a.
  const double rhs = two_E - L * L / I[a];
  const double sb = rhs / (1 / I[b] - 1 / I[a]), sc = rhs / (1 / I[c] - 1 / I[a]);
  std::vector<std::vector<Eigen::Vector3d>> out;
  if (!(sb >= 0 && sc >= 0)) return out;
  for (double sign : {1.0, -1.0}) {
    std::vector<Eigen::Vector3d> curve;
    for (int i = 0; i <= n; ++i) {
      const double phi = 2 * kPi * i / n;
      Eigen::Vector3d p;
      p[b] = std::sqrt(sb) * std::cos(phi);
      p[c] = std::sqrt(sc) * std::sin(phi);
      p[a] = sign * std::sqrt(std::max(0.0, L * L - p[b] * p[b] - p[c] * p[c]));
      curve.push_back(p);
    }
    out.push_back(std::move(curve));
  }
  return out;
}

}  // namespace

std::vector<std::vector<Eigen::Vector3d>> separatrix(const Eigen::Vector3d& I, double L, int n) {
  const double k = std::sqrt((1 / I[0] - 1 / I[1]) / (1 / I[1] - 1 / I[2]));
  std::vector<std::vector<Eigen::Vector3d>> out;
  for (double sign : {1.0, -1.0}) {
    const Eigen::Vector3d u = Eigen::Vector3d(1, 0, sign * k).normalized(), v(0, 1, 0);
    std::vector<Eigen::Vector3d> circle;
    for (int i = 0; i <= n; ++i) {
      const double th = 2 * kPi * i / n;
      circle.push_back(L * (std::cos(th) * u + std::sin(th) * v));
    }
    out.push_back(std::move(circle));
  }
  return out;
}

std::vector<std::vector<Eigen::Vector3d>> polhodes(const Eigen::Vector3d& I, double L, double two_E, int n) {
  const double sep = L * L / I[1];
  if (std::abs(two_E - sep) <= 1e-12 * sep) return separatrix(I, L, n);
  if (two_E > sep) return around(0, I, L, two_E, n);   // near the smallest moment's axis
  return around(2, I, L, two_E, n);                     // near the largest moment's axis
}

void build_momentum_sphere(View& view, const MomentumSphereInput& in, float font_px) {
  const Eigen::Vector3d& I = in.inertia;
  const double L = in.momentum.norm();
  view.camera = Camera{};
  // From the -e1, +e2, +e3 side: +e2 (where a near-intermediate spin starts)
  // and the separatrix arcs towards ±e3 face the viewer.
  view.camera.position = glm::dvec3(-2.9, 3.2, 2.9);
  // Aimed 0.15 above the centre, with 33° of field: the +e3 arrow (1.35)
  // ends below the title band instead of crossing the title.
  view.camera.target = {0, 0, 0.15};
  view.camera.up = {0, 0, 1};
  view.camera.fov_y_deg = 33;
  view.camera.near_m = 0.5;
  view.camera.far_m = 20;
  // An opaque ball a hair inside the sphere hides the curves on its far side.
  view.points.push_back({{0, 0, 0}, 0.985, {0.93f, 0.94f, 0.97f, 1.0f}});
  for (int i = 0; i < 3; ++i) {
    glm::dvec3 e(0);
    e[i] = 1.35;
    view.arrows.push_back({{0, 0, 0}, e, 0.012, kAxisColors[i]});
  }
  if (L <= 0) return;
  const Color family{0.45f, 0.47f, 0.55f, 0.55f}, sep_color{0.85f, 0.1f, 0.1f, 0.95f};
  auto add = [&](const std::vector<std::vector<Eigen::Vector3d>>& curves, Color c, float w) {
    for (const auto& curve : curves) {
      PolylineItem p{{}, c, w, false};
      for (const Eigen::Vector3d& x : curve) p.points.push_back(g(x / L));
      view.polylines.push_back(std::move(p));
    }
  };
  // A family of levels spaced evenly in 2E between L²/I3 and L²/I1.
  const double lo = L * L / I[2], hi = L * L / I[0];
  constexpr int kLevels = 10;
  for (int j = 1; j < kLevels; ++j) {
    const double two_E = lo + (hi - lo) * j / kLevels;
    if (std::abs(two_E - L * L / I[1]) > 1e-3 * (hi - lo)) add(polhodes(I, L, two_E, 96), family, 1.0f);
  }
  // The energy ellipsoid Σ Π_i²/I_i = 2E: its three principal sections.
  const Eigen::Vector3d semi = (in.two_E * I).cwiseSqrt() / L;
  for (int a = 0; a < 3; ++a) {
    PolylineItem e{{}, {0.95f, 0.6f, 0.05f, 0.35f}, 1.0f, false};
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    for (int i = 0; i <= 96; ++i) {
      glm::dvec3 x(0);
      x[b] = semi[b] * std::cos(2 * kPi * i / 96);
      x[c] = semi[c] * std::sin(2 * kPi * i / 96);
      e.points.push_back(x);
    }
    view.polylines.push_back(std::move(e));
  }
  // The body's own polhode under the separatrix, which stays visible on top of it.
  add(polhodes(I, L, in.two_E, 192), {0.95f, 0.6f, 0.05f, 0.9f}, 1.5f);
  add(separatrix(I, L, 192), sep_color, 2.5f);
  PolylineItem path{{}, {0.1f, 0.1f, 0.15f, 1.0f}, 2.5f, true};
  for (const Eigen::Vector3d& p : in.history) path.points.push_back(g(p / L));
  if (path.points.size() >= 2) view.polylines.push_back(std::move(path));
  view.points.push_back({g(in.momentum / L), 0.045, {0.1f, 0.1f, 0.15f, 1.0f}});
  if (!in.title.empty()) view.texts.push_back({in.title, {10.0f, 8.0f}, font_px, {0.12f, 0.13f, 0.16f, 1.0f}});
}

}  // namespace tumble::viz
