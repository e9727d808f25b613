#include "viz/poinsot.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "viz/captions.hpp"
#include "viz/scene_view.hpp"
#include "viz/surfaces.hpp"

namespace tumble::viz {

namespace {

glm::dvec3 g(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

// Two unit vectors spanning the plane ⊥ n.
void plane_basis(const Eigen::Vector3d& n, Eigen::Vector3d& u, Eigen::Vector3d& v) {
  const Eigen::Vector3d a = std::abs(n.z()) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
  u = n.cross(a).normalized();
  v = n.cross(u);
}

}  // namespace

PoinsotGeometry poinsot_geometry(const Eigen::Quaterniond& q, const Eigen::Vector3d& inertia, const Eigen::Vector3d& L) {
  PoinsotGeometry p;
  p.axes = q.toRotationMatrix();
  const Eigen::Vector3d Pi = q.conjugate() * L;
  const Eigen::Vector3d w_principal = Pi.cwiseQuotient(inertia);
  const double two_E = Pi.dot(w_principal);
  p.semi_axes = (two_E * inertia.cwiseInverse()).cwiseSqrt();
  const double Ln = L.norm();
  p.normal = Ln > 0 ? Eigen::Vector3d(L / Ln) : Eigen::Vector3d::UnitZ();
  p.plane_distance = Ln > 0 ? two_E / Ln : 0;
  p.contact = q * w_principal;
  return p;
}

void build_poinsot(View& view, const PoinsotInput& in, float font_px) {
  const PoinsotGeometry p = poinsot_geometry(in.q, in.inertia, in.L);
  const double scale = 1.0 / std::max(p.semi_axes.maxCoeff(), 1e-300);
  // Camera: the plane below the ellipsoid (up = -L̂), seen from 40° above it,
  // so the herpolhode on the plane opens up instead of lying edge-on.
  Eigen::Vector3d u, v;
  plane_basis(p.normal, u, v);
  const Eigen::Vector3d up = -p.normal;
  const Eigen::Vector3d foot = p.plane_distance * scale * p.normal;
  const Eigen::Vector3d target = 0.3 * foot + 0.25 * up;  // the key above the ellipsoid
  view.camera = Camera{};
  view.camera.target = g(target);
  view.camera.position = g(target + 3.6 * (0.85 * u + 0.25 * v).normalized() + 3.0 * up);
  view.camera.up = g(up);
  view.camera.fov_y_deg = 38;
  view.camera.near_m = 0.3;
  view.camera.far_m = 30;
  const double pi = std::numbers::pi;
  // The ellipsoid: a shaded translucent surface fixed to the body, with its
  // three principal sections drawn on it so its turning shows.
  glm::dmat3 axes;
  for (int i = 0; i < 3; ++i) axes[i] = g(p.axes.col(i));
  view.surfaces.push_back(ellipsoid({0, 0, 0}, axes, g(p.semi_axes * scale), kEllipsoidColor));
  const Color ring{0.25f, 0.32f, 0.55f, 0.6f};
  for (int a = 0; a < 3; ++a) {
    PolylineItem section{{}, ring, 1.0f, false};
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    for (int i = 0; i <= 96; ++i) {
      const double ph = 2 * pi * i / 96;
      section.points.push_back(g((p.axes.col(b) * p.semi_axes[b] * std::cos(ph) +
                                  p.axes.col(c) * p.semi_axes[c] * std::sin(ph)) * scale * 1.003));
    }
    view.polylines.push_back(std::move(section));
  }
  for (int i = 0; i < 3; ++i)
    view.arrows.push_back({{0, 0, 0}, g(p.axes.col(i) * p.semi_axes[i] * scale * 1.15), 0.012, kAxisColors[i]});
  // The invariable plane: opaque, centred on the foot of L, with a faint grid
  // a hair above it (towards the ellipsoid) so nothing fights its depth.
  const double half = 1.6, lift = 0.5 * kHerpolhodeLift;
  view.surfaces.push_back(rectangle(g(foot), g(u * half), g(v * half), kPlaneColor));
  const Color grid{0.55f, 0.57f, 0.62f, 0.45f};
  const Eigen::Vector3d on = foot - lift * p.normal;
  for (int i = -4; i <= 4; ++i) {
    const double s = half * i / 4;
    view.polylines.push_back({{g(on + s * u - half * v), g(on + s * u + half * v)}, grid, 1.0f, false});
    view.polylines.push_back({{g(on - half * u + s * v), g(on + half * u + s * v)}, grid, 1.0f, false});
  }
  // L, ω to the contact point, polhode (body-fixed, carried by R) and herpolhode (on the plane).
  // L̂ from the centre to the plane's foot: it meets the plane at a right angle.
  const Eigen::Vector3d L_tip = foot - 3 * kHerpolhodeLift * p.normal;
  view.arrows.push_back({{0, 0, 0}, g(L_tip), 0.015, kLColor});
  view.arrows.push_back({{0, 0, 0}, g(p.contact * scale), 0.015, kOmegaColor});
  PolylineItem polhode{{}, kPolhodeColor, 2.5f, false}, herpolhode{{}, kHerpolhodeColor, 2.0f, false};
  for (const Eigen::Vector3d& w : in.omega_principal_history) polhode.points.push_back(g(in.q * w * scale * 1.006));
  for (const Eigen::Vector3d& w : in.omega_world_history) herpolhode.points.push_back(g(w * scale - kHerpolhodeLift * p.normal));
  view.points.push_back({g(p.contact * scale), 0.035, kHerpolhodeColor});
  if (polhode.points.size() >= 2) view.polylines.push_back(std::move(polhode));
  if (herpolhode.points.size() >= 2) view.polylines.push_back(std::move(herpolhode));
  // The key: each element in its colour, under the view's title; the plane named on itself.
  const float f = font_px, pad = 10.0f;
  float y = 8.0f;
  if (!in.title.empty()) {
    view.texts.push_back({in.title, {pad, y}, f, {0.12f, 0.13f, 0.16f, 1.0f}});
    y += 1.6f * f;
  }
  const std::pair<const char*, Color> key[] = {{"L: angular momentum, normal to the plane", kLColor},
                                               {"ω: angular velocity, to the contact point", kOmegaColor},
                                               {"polhode: ω's path on the ellipsoid", kPolhodeColor},
                                               {"herpolhode: ω's path on the plane", kHerpolhodeColor}};
  for (const auto& [text, color] : key) {
    view.texts.push_back({text, {pad, y}, 0.85f * f, color});
    y += 1.15f * f;
  }
  glm::vec2 px;
  const Eigen::Vector3d corner = foot + 0.9 * half * u - 0.9 * half * v;
  if (project_to_viewport(view.camera, in.width_px, in.height_px, g(corner), px)) {
    const char* name = "invariable plane";
    const float x = std::clamp(px.x - approx_text_width(name, f), 2.0f, in.width_px - approx_text_width(name, f) - 2.0f);
    view.texts.push_back({name, {x, std::clamp(px.y - 1.5f * f, y, in.height_px - 1.3f * f)}, f, {0.35f, 0.37f, 0.42f, 1.0f}});
  }
}

}  // namespace tumble::viz
