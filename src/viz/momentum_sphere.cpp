#include "viz/momentum_sphere.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "viz/captions.hpp"
#include "viz/dashes.hpp"
#include "viz/end_on_mark.hpp"
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
  // The axes are named at their ends: no entry for them.
  std::vector<KeyEntry> out;
  if (in.momentum.norm() <= 0) return out;
  if (in.tracks.empty()) {
    out.push_back(key_entry(Meaning::momentum_point, "\u03a0: L written in body axes"));
    out.push_back(key_entry(Meaning::polhode, "polhode: \u03a0's path"));
  }
  for (std::size_t i = 0; i < in.tracks.size(); ++i) {
    const SphereTrack& t = in.tracks[i];
    const std::string text = t.key.empty() ? t.name : t.key;
    if (t.key.empty() || i == 0 || in.tracks[i - 1].key != t.key) out.push_back({Swatch::line, {t.color}, text});
  }
  if (draws_energy_ellipsoid(in))
    out.push_back({Swatch::block, {color_of(Meaning::energy_ellipsoid, in.ellipsoid_alpha)}, "energy ellipsoid"});
  out.push_back(key_entry(Meaning::separatrix, "separatrix"));
  // The ringed dots; beside a comparison's sphere (a short key in a short view) the axes' names at ±e₂ say it.
  if (in.tracks.empty()) out.push_back({Swatch::dot, {color_of(Meaning::separatrix)}, "saddles \u00b1e\u2082"});
  // Beside several tracks (each method's energy its own) the levels are energies, none the body's;
  // short: the key stands beside a comparison's sphere in a narrow column.
  const std::string levels = in.tracks.empty() ? "other energies" : "levels of E";
  out.push_back(key_entry(Meaning::other_levels, in.level_arrows ? levels + " (arrow: direction)" : levels));
  return out;
}

std::vector<Eigen::Vector3d> own_polhode(const Eigen::Vector3d& I, const Eigen::Vector3d& pi, int n) {
  const double L = pi.norm();
  if (L <= 0) return {};
  const double two_E = pi.cwiseAbs2().cwiseQuotient(I).sum(), sep = L * L / I[1];
  auto curves = polhodes(I, L, two_E, n);
  if (curves.empty() || std::abs(two_E - sep) <= 1e-12 * sep) return {};  // on the separatrix: it is drawn already
  // Two branches, one about +e_a and one about −e_a (a: the pole it circles): Π stays on its own.
  const int a = two_E > sep ? 0 : 2;
  for (auto& c : curves)
    if (!c.empty() && (c.front()[a] >= 0) == (pi[a] >= 0)) return std::move(c);
  return std::move(curves.front());
}

// The separatrix dashed and, with a trail, the path so far (scaled to the unit
// sphere) thinner and under the dashes it runs beside: "just inside the
// separatrix" stays visible (the dashes a hair further out, over it).
void add_separatrix_and_path(View& view, const MomentumSphereInput& in, std::vector<glm::dvec3> path) {
  const float w = in.line_scale;
  const bool drawn = in.trail && path.size() >= 2;
  for (glm::dvec3& x : path) x *= in.path_on_top ? 1.012 : 1.004;
  // Under the separatrix (drawn first), or over it (drawn last, a hair further out).
  if (drawn && !in.path_on_top) view.polylines.push_back({path, color_of(Meaning::polhode), 3.0f * w, false, "polhode"});
  if (drawn && in.path_on_top && !in.reveal.separatrix)
    view.polylines.push_back({path, color_of(Meaning::polhode), 3.0f * w, false, "polhode"});
  if (!in.reveal.separatrix) return;
  for (const auto& circle : separatrix(in.inertia, 1.0, 192)) {
    std::vector<glm::dvec3> unit;
    for (const Eigen::Vector3d& x : circle) unit.push_back(to_glm(x));
    for (auto& dash : dashed(unit, 0.07, 0.045)) {
      for (glm::dvec3& x : dash) x *= in.trail ? 1.008 : 1.0;
      view.polylines.push_back({std::move(dash), color_of(Meaning::separatrix), 1.6f * w, false, "separatrix"});
    }
  }
  if (drawn && in.path_on_top) view.polylines.push_back({std::move(path), color_of(Meaning::polhode), 3.0f * w, false, "polhode"});
}

namespace {

// A family of levels spaced evenly in 2E between L²/I3 and L²/I1 (on the unit
// sphere), each with its direction; dark ones (the palette's grey at 60 %
// brightness, opaque, wider) read on the lit ball from the back of a hall.
void add_other_levels(View& view, const MomentumSphereInput& in) {
  const Eigen::Vector3d& I = in.inertia;
  const double lo = 1 / I[2], hi = 1 / I[0];
  auto level_color = [&](float alpha) {
    glm::vec4 c = color_of(Meaning::other_levels, alpha);
    if (in.dark_levels) c = glm::vec4(glm::vec3(c) * 0.6f, c.a);
    return c;
  };
  const float width = (in.dark_levels ? 2.0f : 1.2f) * in.line_scale;
  for (int j = 1; j < in.levels; ++j) {
    const double two_E = lo + (hi - lo) * j / in.levels;
    if (std::abs(two_E - 1 / I[1]) <= 1e-3 * (hi - lo)) continue;
    for (const auto& c : polhodes(I, 1.0, two_E, 96)) {
      std::vector<glm::dvec3> points;
      for (const Eigen::Vector3d& x : c) points.push_back(to_glm(x));
      view.polylines.push_back({std::move(points), level_color(in.dark_levels ? 1.0f : 0.55f), width, false});
      if (in.level_arrows)
        add_direction_arrows(view, c, I, 1, level_color(in.dark_levels ? 1.0f : 0.8f), in.dark_levels ? 0.13 : 0.09);
    }
  }
}

// Each track's path so far, a hair outside the sphere (`paths`), and its dot now (`dots`), in its own colour.
void add_tracks(View& view, const MomentumSphereInput& in, double L, bool paths, bool dots) {
  const float w = in.line_scale;
  for (const SphereTrack& t : in.tracks) {
    if (t.path.empty()) continue;
    std::vector<glm::dvec3> path;
    for (const Eigen::Vector3d& x : t.path) path.push_back(1.004 * to_glm(x / L));
    if (paths && path.size() >= 2)
      view.polylines.push_back({path, t.color, 3.0f * w * t.width, false, t.reported ? "polhode " + t.name : ""});
    if (!dots) continue;
    // Its dot, unless the ball hides it (behind the ball, inside its outline).
    const glm::dvec3 p = 1.02 * to_glm(t.path.back() / L), d = glm::normalize(view.camera.position - view.camera.target);
    if (glm::dot(p, d) < 0 && glm::length(p - glm::dot(p, d) * d) < kSphereBall) continue;
    view.points.push_back({p, 0.03 * w, t.color, ""});  // unnamed: several dots would crowd the axes' names off their tips
  }
}

}  // namespace

void build_momentum_sphere(View& view, const MomentumSphereInput& in) {
  const Eigen::Vector3d& I = in.inertia;
  const double L = in.momentum.norm();
  view.name = "momentum_sphere";
  view.camera = sphere_camera(in.pose, in.camera);
  if (in.fit_radius > 0) view.camera.fov_y_deg = fov_for_ball(view.camera, in.fit_radius, in.width_px / in.height_px);
  view.ball_px = ball_on_screen(view.camera, in.width_px, in.height_px);
  // An opaque ball a hair inside the sphere hides the curves on its far side.
  view.points.push_back({{0, 0, 0}, kSphereBall, kSphereBallColor});
  if (L <= 0) {
    add_sphere_axes(view, in.width_px, in.height_px, text_px(TextRole::label, in.frame_h, in.text_scale));
    return;
  }
  if (draws_energy_ellipsoid(in) && in.ellipsoid_alpha > 0) {
    view.surfaces.push_back(energy_ellipsoid(I, L, in.two_E));
    view.surfaces.back().color.a = in.ellipsoid_alpha;
  }
  auto scaled = [&](const std::vector<Eigen::Vector3d>& curve) {
    std::vector<glm::dvec3> out;
    for (const Eigen::Vector3d& x : curve) out.push_back(to_glm(x / L));
    return out;
  };
  auto unit = [&](const std::vector<Eigen::Vector3d>& curve) {
    std::vector<Eigen::Vector3d> u;
    for (const Eigen::Vector3d& x : curve) u.push_back(x / L);
    return u;
  };
  if (in.reveal.curves) add_other_levels(view, in);
  const float w = in.line_scale;
  // Everything from here on shows through the ball, faintly, where it is behind it.
  const std::size_t front_first = view.polylines.size();
  add_sphere_axis_lines(view);
  add_end_on_marks(view, kAxisReach, 0.05);
  // The body's own polhode, wide, then the separatrix dashed over it: where
  // the two run together both stay visible (crimson edges, sky-blue dashes).
  const bool whole = in.reveal.curves && (!in.trail || in.reveal.whole_polhode);
  const auto own = whole ? own_polhode(I, in.momentum, 192) : std::vector<Eigen::Vector3d>{};
  // Kept faint where Π travels: the whole loop it is on stays in sight ahead of it.
  if (!whole && in.trail && in.faint_polhode && in.reveal.curves && in.tracks.empty())
    view.polylines.push_back({scaled(own_polhode(I, in.momentum, 192)), color_of(Meaning::polhode, 0.3f), 4.5f * w, false});
  if (!own.empty()) {
    view.polylines.push_back({scaled(own), color_of(Meaning::polhode), 4.5f * w, false, "polhode"});
    add_direction_arrows(view, unit(own), I, 4, color_of(Meaning::polhode), 0.13);
  }
  // Tracks under the separatrix's dashes (a path beside it leaves it seen), or over them.
  if (in.tracks_under_separatrix) add_tracks(view, in, L, true, false);
  add_separatrix_and_path(view, in, in.tracks.empty() ? scaled(in.history) : std::vector<glm::dvec3>{});
  if (in.reveal.separatrix) add_saddles(view);
  if (!in.tracks.empty()) {
    add_tracks(view, in, L, !in.tracks_under_separatrix, true);
  } else {
    // Π now: a dot standing out of the sphere, over every curve, small enough that a saddle it sits near shows.
    view.points.push_back({1.02 * to_glm(in.momentum / L), 0.03 * w * in.dot_scale, color_of(Meaning::momentum_point), "momentum_point"});
  }
  // Named last: clear of the curves too, not pushed later by lines onto the ball's face.
  name_sphere_axes(view, in.width_px, in.height_px, text_px(TextRole::label, in.frame_h, in.text_scale), in.hide_far_side);
  show_far_side(view, front_first, kSphereBall, in.hide_far_side);
}

}  // namespace tumble::viz
