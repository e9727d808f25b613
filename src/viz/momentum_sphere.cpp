#include "viz/momentum_sphere.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "viz/captions.hpp"
#include "viz/key.hpp"
#include "viz/scene_view.hpp"
#include "viz/surfaces.hpp"
#include "viz/text_layout.hpp"

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

namespace {

// Whether `box` lies on one of the three +e_i arrows (thickened by `head_px`) as `project` draws them.
bool on_an_axis(const ViewportProjection& project, const Box& box, float head_px) {
  glm::vec2 base, tip;
  if (!project(glm::dvec3(0), base)) return false;
  for (int i = 0; i < 3; ++i) {
    glm::dvec3 e(0);
    e[i] = 1.35;
    if (!project(e, tip)) continue;
    for (int s = 0; s <= 24; ++s) {
      const glm::vec2 p = base + (tip - base) * (static_cast<float>(s) / 24);
      const float r = s == 24 ? head_px + 1 : 2.5f;
      if (p.x + r > box.x0 && p.x - r < box.x1 && p.y + r > box.y0 && p.y - r < box.y1) return true;
    }
  }
  return false;
}

// The axes through the sphere, +e_i arrows and −e_i lines, each +tip named e_i
// where the ball does not hide it: just beyond the arrow's head on screen,
// along the axis as drawn (beside it when the axis points at the camera), so
// the label never sits on its own arrow.
void add_axes(View& view, const MomentumSphereInput& in) {
  static const char* const kNames[3] = {"e\u2081", "e\u2082", "e\u2083"};  // e₁ e₂ e₃
  const float size = text_px(TextRole::label, in.frame_h);
  const ViewportProjection project(view.camera, in.width_px, in.height_px);
  // The sphere's radius on screen (a perspective silhouette is a little wider than |L|).
  glm::vec2 c0, c1;
  const glm::dvec3 side = glm::normalize(glm::cross(view.camera.target - view.camera.position, view_up(view.camera)));
  const float ball_px = project(glm::dvec3(0), c0) && project(1.06 * side, c1) ? glm::length(c1 - c0) : 0.0f;
  for (int i = 0; i < 3; ++i) {
    glm::dvec3 e(0);
    e[i] = 1.35;
    view.arrows.push_back({{0, 0, 0}, e, 0.012, kAxisColors[i], std::string("axis") + char('1' + i)});
    view.polylines.push_back({{glm::dvec3(0), -e}, color_of(static_cast<Meaning>(i), 0.6f), 1.5f, false});
    glm::vec2 tip, base, head;
    if (hidden_by_ball(view.camera.position, e, kSphereBall) || !project(e, tip) || !project(glm::dvec3(0), base) ||
        !project(e + 0.029 * glm::normalize(view.camera.up), head))
      continue;
    TextItem t{kNames[i], {0, 0}, size, kAxisColors[i]};
    const InkSpan ink = text_ink(t.text, size);
    const glm::vec2 along = tip - base;
    const float len = glm::length(along);
    const glm::vec2 d0 = len > 0.25f * size ? along / len : glm::vec2(0, -1);
    // The tip in front of the ball: the label at its rim, off the curves on it.
    const glm::vec2 from = len < ball_px ? base + ball_px * d0 : tip;
    // Along the axis as drawn, else turned a little at a time until clear of the three arrows.
    for (const float turn : {0.0f, 0.45f, -0.45f, 0.9f, -0.9f, 1.35f, -1.35f, 1.8f, -1.8f}) {
      const glm::vec2 d{d0.x * std::cos(turn) - d0.y * std::sin(turn), d0.x * std::sin(turn) + d0.y * std::cos(turn)};
      // Past the head (its screen radius) and half the label's box along d, plus a gap.
      const float reach = glm::length(head - tip) + 0.5f * (std::abs(d.x) * ink.width() + std::abs(d.y) * size) + 0.25f * size;
      const glm::vec2 centre = from + reach * d;
      t.position_px = {centred_x(t.text, size, centre.x), centre.y - 0.5f * size};
      if (!on_an_axis(project, text_box(t), glm::length(head - tip))) break;
    }
    t.name = std::string("axis_label_e") + char('1' + i);
    view.texts.push_back(std::move(t));
  }
}

}  // namespace

bool draws_energy_ellipsoid(const MomentumSphereInput& in) {
  // Only while it fits inside the axes' reach: near e₁ its e₃ semi-axis is √(I₃/I₁) |L| and would fill the view.
  const double L = in.momentum.norm();
  return in.energy_ellipsoid && L > 0 && in.two_E > 0 && std::sqrt(in.two_E * in.inertia[2]) / L <= kEnergyEllipsoidReach;
}

std::vector<KeyEntry> sphere_key(const MomentumSphereInput& in) {
  std::vector<KeyEntry> out{
      {Swatch::line, {kAxisColors[0], kAxisColors[1], kAxisColors[2]}, "e\u2081 e\u2082 e\u2083: I\u2081 < I\u2082 < I\u2083"}};
  if (in.momentum.norm() <= 0) return out;  // only the axes are drawn
  out.push_back(key_entry(Meaning::momentum_point, "\u03a0: L in body axes"));
  out.push_back(key_entry(Meaning::polhode, "polhode (\u03a0's path)"));
  if (draws_energy_ellipsoid(in)) out.push_back({Swatch::block, {color_of(Meaning::polhode, 0.35f)}, "energy ellipsoid"});
  out.push_back(key_entry(Meaning::separatrix, "separatrix"));
  out.push_back(key_entry(Meaning::other_levels, "other energies"));
  return out;
}

SurfaceItem energy_ellipsoid(const Eigen::Vector3d& I, double L, double two_E) {
  // Σ Π_i²/I_i = 2E in units of |L|: semi-axes √(2E I_i)/|L|, the principal axes its own.
  const glm::dvec3 semi(std::sqrt(two_E * I[0]) / L, std::sqrt(two_E * I[1]) / L, std::sqrt(two_E * I[2]) / L);
  SurfaceItem s = ellipsoid({0, 0, 0}, glm::dmat3(1.0), semi, color_of(Meaning::polhode, 0.22f));
  return s;  // unnamed: a key may cover its caps (keep_clear), never the sphere

}

float sphere_shift_room(float width_px, float height_px) {
  // The sphere's radius is a third of the height (fov: ±1.5 |L|); it keeps its side margin.
  return std::max(0.0f, 0.5f * width_px - height_px / 3.0f - 0.02f * height_px);
}

void build_momentum_sphere(View& view, const MomentumSphereInput& in) {
  const Eigen::Vector3d& I = in.inertia;
  const double L = in.momentum.norm();
  view.name = "momentum_sphere";
  view.camera = sphere_camera(in.pose, in.camera);
  if (in.fit_radius > 0) view.camera.fov_y_deg = fov_for_ball(view.camera, in.fit_radius, in.width_px / in.height_px);
  const float top = add_view_title(view, in.title, in.width_px, in.frame_h);
  if (in.key) {
    const float size = text_px(TextRole::key, in.frame_h);
    const std::vector<KeyEntry> entries = sphere_key(in);
    KeySpot spot;  // by default bottom-left, the sphere moved right by half the key's width so they part
    const glm::vec2 k = key_size(entries, size);
    spot.top_left = {0.5f * size, std::max(top, in.height_px - k.y - 0.5f * size)};
    spot.shift_px = std::min(0.5f * k.x, sphere_shift_room(in.width_px, in.height_px));
    if (in.key_spot) spot = *in.key_spot;
    add_key(view, entries, spot.top_left, size);
    shift_content(view, spot.shift_px, in.height_px);
  }
  // An opaque ball a hair inside the sphere hides the curves on its far side.
  view.points.push_back({{0, 0, 0}, kSphereBall, {0.93f, 0.94f, 0.97f, 1.0f}});
  add_axes(view, in);
  if (L <= 0) return;
  if (!in.outline_only && draws_energy_ellipsoid(in)) view.surfaces.push_back(energy_ellipsoid(I, L, in.two_E));
  auto add = [&](const std::vector<std::vector<Eigen::Vector3d>>& curves, Color c, float w, const char* name) {
    for (const auto& curve : curves) {
      PolylineItem p{{}, c, w, false, name};
      for (const Eigen::Vector3d& x : curve) p.points.push_back(g(x / L));
      view.polylines.push_back(std::move(p));
    }
  };
  // A family of levels spaced evenly in 2E between L²/I3 and L²/I1.
  const double lo = L * L / I[2], hi = L * L / I[0];
  constexpr int kLevels = 10;
  for (int j = 1; j < kLevels && !in.outline_only; ++j) {
    const double two_E = lo + (hi - lo) * j / kLevels;
    if (std::abs(two_E - L * L / I[1]) > 1e-3 * (hi - lo))
      add(polhodes(I, L, two_E, 96), color_of(Meaning::other_levels, 0.5f), 1.0f, "");
  }
  // The body's own polhode under the separatrix, which stays visible on top of it.
  add(polhodes(I, L, in.two_E, 192), color_of(Meaning::polhode, 0.9f), 2.0f, "polhode");
  if (!in.outline_only) add(separatrix(I, L, 192), color_of(Meaning::separatrix, 0.95f), 2.5f, "separatrix");
  PolylineItem path{{}, color_of(Meaning::momentum_point), 2.5f, true, "momentum_path"};
  for (const Eigen::Vector3d& p : in.history) path.points.push_back(g(p / L));
  if (path.points.size() >= 2) view.polylines.push_back(std::move(path));
  view.points.push_back({g(in.momentum / L), 0.045, color_of(Meaning::momentum_point), "momentum_point"});
}

}  // namespace tumble::viz
