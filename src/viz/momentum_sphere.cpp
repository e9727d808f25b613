#include "viz/momentum_sphere.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "viz/captions.hpp"
#include "viz/sphere_figure.hpp"
#include "viz/key.hpp"
#include "viz/scene_view.hpp"
#include "viz/surfaces.hpp"
#include "viz/text_layout.hpp"

namespace tumble::viz {

namespace {

constexpr double kPi = std::numbers::pi;

// Around axis `a` (0 or 2): the other two components on an ellipse, Π_a from
// the sphere; the parameter refined where the curve bends (near ±e2 a level
// close to the separatrix turns within a few thousandths of |L|).
std::vector<std::vector<Eigen::Vector3d>> around(int a, const Eigen::Vector3d& I, double L, double two_E, int n) {
  const int b = a == 0 ? 1 : 0, c = a == 0 ? 2 : 1;
  // Eliminating Π_a: Π_b²(1/I_b - 1/I_a) + Π_c²(1/I_c - 1/I_a) = 2E - L²/I_a.
  const double rhs = two_E - L * L / I[a];
  const double sb = rhs / (1 / I[b] - 1 / I[a]), sc = rhs / (1 / I[c] - 1 / I[a]);
  std::vector<std::vector<Eigen::Vector3d>> out;
  if (!(sb >= 0 && sc >= 0)) return out;
  for (double sign : {1.0, -1.0}) {
    auto at = [&](double phi) {
      Eigen::Vector3d p;
      p[b] = std::sqrt(sb) * std::cos(phi);
      p[c] = std::sqrt(sc) * std::sin(phi);
      p[a] = sign * std::sqrt(std::max(0.0, L * L - p[b] * p[b] - p[c] * p[c]));
      return p;
    };
    std::vector<double> phis;
    for (int i = 0; i <= n; ++i) phis.push_back(2 * kPi * i / n);
    out.push_back(refined_curve(at, phis, 5e-4 * L));
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

bool draws_energy_ellipsoid(const MomentumSphereInput& in) {
  // Only while it fits inside the axes' reach: near e₁ its e₃ semi-axis is √(I₃/I₁) |L| and would fill the view.
  const double L = in.momentum.norm();
  return in.energy_ellipsoid && L > 0 && in.two_E > 0 && std::sqrt(in.two_E * in.inertia[2]) / L <= kEnergyEllipsoidReach;
}

std::vector<KeyEntry> sphere_key(const MomentumSphereInput& in) {
  std::vector<KeyEntry> out{
      {Swatch::line, {kAxisColors[0], kAxisColors[1], kAxisColors[2]}, "\u00b1e\u2081 \u00b1e\u2082 \u00b1e\u2083: I\u2081 < I\u2082 < I\u2083"}};
  if (in.momentum.norm() <= 0) return out;  // only the axes are drawn
  out.push_back(key_entry(Meaning::momentum_point, "\u03a0: L in body axes"));
  out.push_back(key_entry(Meaning::polhode, "polhode (arrows: \u03a0's way)"));
  if (draws_energy_ellipsoid(in))
    out.push_back({Swatch::block, {color_of(Meaning::energy_ellipsoid, kEnergyEllipsoidAlpha)}, "energy ellipsoid"});
  out.push_back(key_entry(Meaning::separatrix, "separatrix"));
  out.push_back({Swatch::dot, {color_of(Meaning::separatrix)}, "saddles \u00b1e\u2082"});
  out.push_back(key_entry(Meaning::other_levels, "other energies"));
  return out;
}

void build_momentum_sphere(View& view, const MomentumSphereInput& in) {
  const Eigen::Vector3d& I = in.inertia;
  const double L = in.momentum.norm();
  view.name = "momentum_sphere";
  view.camera = sphere_camera(in.pose, in.camera);
  if (in.fit_radius > 0) view.camera.fov_y_deg = fov_for_ball(view.camera, in.fit_radius, in.width_px / in.height_px);
  // An opaque ball a hair inside the sphere hides the curves on its far side.
  view.points.push_back({{0, 0, 0}, kSphereBall, {0.93f, 0.94f, 0.97f, 1.0f}});
  add_sphere_axes(view, in.width_px, in.height_px, text_px(TextRole::label, in.frame_h));
  if (L <= 0) return;
  if (draws_energy_ellipsoid(in)) view.surfaces.push_back(energy_ellipsoid(I, L, in.two_E));
  auto add = [&](const std::vector<std::vector<Eigen::Vector3d>>& curves, Color c, float w, const char* name) {
    for (const auto& curve : curves) {
      PolylineItem p{{}, c, w, false, name};
      for (const Eigen::Vector3d& x : curve) p.points.push_back(to_glm(x / L));
      view.polylines.push_back(std::move(p));
    }
  };
  auto unit = [&](const std::vector<Eigen::Vector3d>& curve) {
    std::vector<Eigen::Vector3d> u;
    for (const Eigen::Vector3d& x : curve) u.push_back(x / L);
    return u;
  };
  // A family of levels spaced evenly in 2E between L²/I3 and L²/I1, each with its direction.
  const double lo = L * L / I[2], hi = L * L / I[0];
  constexpr int kLevels = 10;
  for (int j = 1; j < kLevels; ++j) {
    const double two_E = lo + (hi - lo) * j / kLevels;
    if (std::abs(two_E - L * L / I[1]) <= 1e-3 * (hi - lo)) continue;
    const auto curves = polhodes(I, L, two_E, 96);
    add(curves, color_of(Meaning::other_levels, 0.5f), 1.0f, "");
    for (const auto& c : curves) add_direction_arrows(view, unit(c), I, 1, color_of(Meaning::other_levels, 0.8f), 0.09);
  }
  // Everything from here on shows through the ball, faintly, where it is behind it.
  const std::size_t front_first = view.polylines.size();
  // The separatrix wide, the body's own polhode narrow on top of it: near it
  // the two nearly coincide, and both stay visible (sky-blue edges, magenta core).
  add(separatrix(I, L, 192), color_of(Meaning::separatrix, 0.95f), 4.5f, "separatrix");
  const auto own = polhodes(I, L, in.two_E, 192);
  add(own, color_of(Meaning::polhode), 2.0f, "polhode");
  for (const auto& c : own) add_direction_arrows(view, unit(c), I, 4, color_of(Meaning::polhode), 0.13);
  add_saddles(view);
  view.points.push_back({to_glm(in.momentum / L), 0.045, color_of(Meaning::momentum_point), "momentum_point"});
  show_far_side(view, front_first, kSphereBall);
  // Π's recent path, on the near side only (its fade runs oldest to newest).
  PolylineItem path{{}, color_of(Meaning::momentum_point, 0.8f), 2.0f, true, "momentum_path"};
  for (const Eigen::Vector3d& p : in.history) path.points.push_back(to_glm(p / L));
  if (path.points.size() >= 2) view.polylines.push_back(std::move(path));
}

}  // namespace tumble::viz
