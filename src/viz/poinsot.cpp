#include "viz/poinsot.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "viz/captions.hpp"
#include "viz/dashes.hpp"
#include "viz/momentum_sphere.hpp"
#include "viz/key.hpp"
#include "viz/scene_view.hpp"
#include "viz/surfaces.hpp"
#include "viz/text_layout.hpp"

namespace tumble::viz {

namespace {

// Two unit vectors spanning the plane ⊥ n, as a world or body_frame view's
// camera across −L spans it (compose::across_camera: u the side nearest world
// −y, v = −n × u), so the same azimuth and elevation look from the same
// direction in both and e₁ points the same way in them.
void plane_basis(const Eigen::Vector3d& n, Eigen::Vector3d& u, Eigen::Vector3d& v) {
  u = -Eigen::Vector3d::UnitY() + n.y() * n;
  if (u.norm() < 1e-3) u = Eigen::Vector3d::UnitX() - n.x() * n;
  u.normalize();
  v = (-n).cross(u);
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

std::vector<KeyEntry> poinsot_key(bool separatrix) {
  // The axes, L and ω as every view of bodies names them (one entry each in a
  // frame's key); the plane and the two curves carry their names beside them.
  std::vector<KeyEntry> out{
      {Swatch::line, {kAxisColors[0], kAxisColors[1], kAxisColors[2]}, "e\u2081 e\u2082 e\u2083: I\u2081 < I\u2082 < I\u2083"},
      key_entry(Meaning::L, separatrix ? "L" : "L: angular momentum"),
      key_entry(Meaning::omega, separatrix ? "\u03c9" : "\u03c9: angular velocity"),
      {Swatch::dot, {color_of(Meaning::omega)}, "contact point"},
      {Swatch::dot, {color_of(Meaning::polhode)}, "polhode's start"},
      key_entry(Meaning::ellipsoid, "inertia ellipsoid")};
  if (separatrix) out.push_back(key_entry(Meaning::separatrix, "separatrix"));
  return out;
}

std::vector<std::vector<Eigen::Vector3d>> ellipsoid_separatrix(const Eigen::Vector3d& inertia, double two_E, int n) {
  auto curves = separatrix(inertia, std::sqrt(std::max(two_E, 0.0) * inertia[1]), n);
  for (auto& c : curves)
    for (Eigen::Vector3d& x : c) x = x.cwiseQuotient(inertia);
  return curves;
}

namespace {

// Line widths grow with the frame (1 at 540 lines, 2 at 1080): a curve keeps its weight beside the text.
float line_scale(int frame_h) { return std::max(1.0f, static_cast<float>(frame_h) / 540.0f); }

// Poinsot's construction, scaled so the largest semi-axis is 1: the plane
// spanned by (u, v) ⊥ L̂, its foot the nearest point to the centre.
struct PoinsotFrame {
  PoinsotGeometry p;
  double scale;
  Eigen::Vector3d u, v, foot;
};

// The camera: the plane below the ellipsoid (up = -L̂), seen from in.camera
// (by default 40° above it, so the herpolhode opens up instead of lying edge-on).
void aim_poinsot_camera(View& view, const PoinsotFrame& f, const SphereCameraSettings& c, bool close_up) {
  const Eigen::Vector3d up = -f.p.normal;
  // Halfway from the centre to the plane: the ellipsoid fills the view; close up, the foot of L (the curves are round it).
  const Eigen::Vector3d target = close_up ? f.foot : Eigen::Vector3d(0.5 * f.foot);
  view.camera = Camera{};
  view.name = "poinsot";
  view.camera.target = to_glm(target);
  const double az = glm::radians(c.azimuth_deg), el = glm::radians(c.elevation_deg);
  view.camera.position = to_glm(target + c.distance * (std::cos(el) * (std::cos(az) * f.u + std::sin(az) * f.v) + std::sin(el) * up));
  view.camera.up = to_glm(up);
  view.camera.fov_y_deg = 38;
  view.camera.near_m = 0.3;
  view.camera.far_m = 30;
}

// The ellipsoid: a shaded translucent surface fixed to the body, with its
// three principal sections drawn on it so its turning shows.
void add_inertia_ellipsoid(View& view, const PoinsotFrame& f, float w, bool axes_too) {
  const PoinsotGeometry& p = f.p;
  const double pi = std::numbers::pi;
  glm::dmat3 axes;
  for (int i = 0; i < 3; ++i) axes[i] = to_glm(p.axes.col(i));
  view.surfaces.push_back(ellipsoid({0, 0, 0}, axes, to_glm(p.semi_axes * f.scale), color_of(Meaning::ellipsoid, 0.32f)));
  view.surfaces.back().name = "ellipsoid";
  const Color ring = color_of(Meaning::ellipsoid, 0.6f);
  for (int a = 0; a < 3; ++a) {
    PolylineItem section{{}, ring, 1.2f * w, false};
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    for (int i = 0; i <= 96; ++i) {
      const double ph = 2 * pi * i / 96;
      section.points.push_back(to_glm((p.axes.col(b) * p.semi_axes[b] * std::cos(ph) +
                                  p.axes.col(c) * p.semi_axes[c] * std::sin(ph)) * f.scale * 1.003));
    }
    view.polylines.push_back(std::move(section));
  }
  // The axes end on the ellipsoid's surface, where ω ends too (far outside a close-up: not drawn there).
  if (!axes_too) return;
  static const char* const kNames[3] = {"e\u2081", "e\u2082", "e\u2083"};
  for (int i = 0; i < 3; ++i)
    view.arrows.push_back({{0, 0, 0}, to_glm(p.axes.col(i) * p.semi_axes[i] * f.scale), 0.012, kAxisColors[i],
                           std::string("e") + char('1' + i), kNames[i], 2});
}

// The invariable plane: opaque, centred on the foot of L, with a faint grid
// a hair above it (towards the ellipsoid) so nothing fights its depth.
void add_invariable_plane(View& view, const PoinsotFrame& f) {
  const double half = 1.6, lift = 0.5 * kHerpolhodeLift;
  view.surfaces.push_back(rectangle(to_glm(f.foot), to_glm(f.v * half), to_glm(f.u * half), kPlaneColor));  // normal v × u = L̂
  view.surfaces.back().name = "plane";
  const Color grid = color_of(Meaning::plane, 0.45f);
  const Eigen::Vector3d on = f.foot - lift * f.p.normal;
  for (int i = -4; i <= 4; ++i) {
    const double s = half * i / 4;
    view.polylines.push_back({{to_glm(on + s * f.u - half * f.v), to_glm(on + s * f.u + half * f.v)}, grid, 1.0f, false});
    view.polylines.push_back({{to_glm(on - half * f.u + s * f.v), to_glm(on + half * f.u + s * f.v)}, grid, 1.0f, false});
  }
}

// The polhode's runs on the ellipsoid's near side, drawn again over the glass
// in full colour: the whole curve shows as one closed loop, its far side
// dimmed through the ellipsoid, its near side not.
void add_near_side(View& view, const PoinsotFrame& f, const PolylineItem& curve) {
  const Eigen::Vector3d eye(view.camera.position.x, view.camera.position.y, view.camera.position.z);
  const Eigen::Vector3d a = f.p.semi_axes * f.scale;
  auto near = [&](const glm::dvec3& q) {
    const Eigen::Vector3d x(q.x, q.y, q.z);
    const Eigen::Vector3d n = f.p.axes * (f.p.axes.transpose() * x).cwiseQuotient(a.cwiseProduct(a));  // outward normal
    return n.dot(eye - x) > 0;
  };
  std::size_t start = 0;
  while (start + 1 < curve.points.size()) {
    const bool shown = near(curve.points[start]);
    std::size_t end = start + 1;
    while (end + 1 < curve.points.size() && near(curve.points[end]) == shown) ++end;
    if (shown) {
      PolylineItem run{{}, curve.color, curve.width_px, false};
      run.over_glass = true;
      run.points.assign(curve.points.begin() + static_cast<long>(start), curve.points.begin() + static_cast<long>(end) + 1);
      view.polylines.push_back(std::move(run));
    }
    start = end;
  }
}

// L, ω to the contact point, polhode (body-fixed, carried by R) and herpolhode (on the plane).
void add_motion(View& view, const PoinsotFrame& f, const PoinsotInput& in) {
  const PoinsotGeometry& p = f.p;
  // L̂ from the centre to the plane's foot: it meets the plane at a right angle.
  const Eigen::Vector3d L_tip = f.foot - 3 * kHerpolhodeLift * p.normal;
  if (!in.close_up) {  // close up, their heads would cover the curves they point to
    view.arrows.push_back({{0, 0, 0}, to_glm(L_tip), 0.022, kLColor, "L", "L", 0});  // bold: the construction's two vectors
    view.arrows.push_back({{0, 0, 0}, to_glm(p.contact * f.scale), 0.022, kOmegaColor, "omega", "\u03c9", 1});
  }
  const float w = line_scale(in.frame_h);
  PolylineItem polhode{{}, color_of(Meaning::polhode), 2.5f * w, false, "polhode"};
  // The herpolhode thinner than the polhode and fading with age (oldest faint):
  // box 1's turns round and round, and drawn at one weight its loops fill a ring.
  PolylineItem herpolhode{{}, color_of(Meaning::herpolhode), 1.7f * w, true, "herpolhode"};
  herpolhode.over_glass = true;  // under the ellipsoid's glass, seen through it in full colour (not tinted away)
  for (const Eigen::Vector3d& w : in.omega_principal_history) polhode.points.push_back(to_glm(in.q * w * f.scale * 1.006));
  for (const Eigen::Vector3d& w : in.omega_world_history)
    herpolhode.points.push_back(to_glm(w * f.scale - kHerpolhodeLift * p.normal));
  // Where ω started on the ellipsoid: the loop is seen to close when it comes back to it.
  if (!polhode.points.empty())
    view.points.push_back({polhode.points.front(), 0.6 * kContactDotRadius * in.dot_scale, polhode.color, "polhode_start"});
  // The contact point, where the ellipsoid touches the plane: the eye's first stop.
  view.points.push_back({to_glm(p.contact * f.scale), kContactDotRadius * in.dot_scale, color_of(Meaning::omega), "contact_point"});
  if (polhode.points.size() >= 2) add_near_side(view, f, polhode);
  if (polhode.points.size() >= 2) view.polylines.push_back(std::move(polhode));
  if (herpolhode.points.size() >= 2) view.polylines.push_back(std::move(herpolhode));
}

// The separatrix dashed on the ellipsoid (a hair outside it, as the polhode),
// its near side over the glass: box 2's polhode is seen to run just beside it.
// Unnamed, as the principal sections: a reference drawn on the ellipsoid, which
// labels may cross, not a curve the motion draws.
void add_separatrix(View& view, const PoinsotFrame& f, const PoinsotInput& in) {
  const Eigen::Vector3d I = in.inertia;
  const double two_E = f.p.semi_axes[0] * f.p.semi_axes[0] * I[0];
  const float w = line_scale(in.frame_h);
  for (const auto& curve : ellipsoid_separatrix(I, two_E, 192)) {
    std::vector<glm::dvec3> world;
    for (const Eigen::Vector3d& x : curve) world.push_back(to_glm(in.q * x * f.scale * 1.004));
    for (auto& dash : dashed(world, 0.08, 0.04)) {  // bold: it must read through the glass beside the polhode
      PolylineItem d{std::move(dash), color_of(Meaning::separatrix), 2.4f * w, false};
      add_near_side(view, f, d);
      view.polylines.push_back(std::move(d));
    }
  }
}

// A curve's name beside its extent on screen (the extent is the label's
// subject: compose/label_pins pins it once per run beside where the curve went).
void add_curve_label(View& view, const ViewportProjection& project, const PolylineItem& curve, const char* text, float size,
                     const char* name) {
  glm::vec4 box{1e30f, 1e30f, -1e30f, -1e30f};
  for (const glm::dvec3& p : curve.points) {
    glm::vec2 px;
    if (!project(p, px)) continue;
    box = {std::min(box.x, px.x), std::min(box.y, px.y), std::max(box.z, px.x), std::max(box.w, px.y)};
  }
  if (box.z < box.x) return;
  const glm::vec2 c{0.5f * (box.x + box.z), 0.5f * (box.y + box.w)};
  TextItem t{text, {centred_x(text, size, c.x), c.y - 0.5f * size}, size, curve.color, name};
  t.subject_px = box + glm::vec4(-4, -4, 4, 4);
  t.leader_to = curve.name;
  view.texts.push_back(std::move(t));
}

// The polhode and the herpolhode named beside them, the plane at a corner clear of the ellipsoid.
void add_direct_labels(View& view, const PoinsotFrame& f, const PoinsotInput& in) {
  // A close-up is an inset in a view that names them, in the same colours: in its small space names would crowd the curves.
  if (in.close_up) return;
  const ViewportProjection project(view.camera, in.width_px, in.height_px);
  const float size = text_px(TextRole::label, in.frame_h, in.text_scale);
  for (const PolylineItem& l : view.polylines) {
    // Each named with a leader to its curve: beside its extent alone, the
    // polhode's name could land on the plane by the herpolhode's.
    if (l.name == "polhode") add_curve_label(view, project, l, "polhode", size, "label_polhode");
    if (l.name == "herpolhode") add_curve_label(view, project, l, "herpolhode", size, "label_herpolhode");
  }
  // The plane at the point in view farthest on screen from the foot of L (the ellipsoid and the curves are round it).
  glm::vec2 foot;
  if (!in.name_plane || !project(to_glm(f.foot), foot)) return;
  glm::dvec3 corner(0);
  float farthest = -1;
  // Corners, then nearer points and the edges' middles: a close camera may not see the corners.
  for (double r : {1.2, 0.9})
    for (double a : {-1.0, 0.0, 1.0})
      for (double b : {-1.0, 0.0, 1.0}) {
        if (a == 0 && b == 0) continue;
        const glm::dvec3 c = to_glm(f.foot + r * (a * f.u + b * f.v));
        glm::vec2 px;
        const bool shown = project(c, px) && px.x > 0 && px.x < in.width_px && px.y > 0 && px.y < in.height_px;
        if (shown && glm::length(px - foot) > farthest) farthest = glm::length(px - foot), corner = c;
      }
  glm::vec2 px;
  if (farthest < 0 || !project(corner, px)) return;
  TextItem t{"invariable plane", {centred_x("invariable plane", size, px.x), px.y - 0.5f * size}, size,
             color_of(Meaning::ink), "label_plane"};
  t.subject_px = {px.x - 4, px.y - 4, px.x + 4, px.y + 4};
  view.texts.push_back(std::move(t));
}

}  // namespace

void build_poinsot(View& view, const PoinsotInput& in) {
  PoinsotFrame f{poinsot_geometry(in.q, in.inertia, in.L), 0, {}, {}, {}};
  f.scale = 1.0 / std::max(f.p.semi_axes.maxCoeff(), 1e-300);
  plane_basis(f.p.normal, f.u, f.v);
  f.foot = f.p.plane_distance * f.scale * f.p.normal;
  aim_poinsot_camera(view, f, in.camera, in.close_up);
  add_inertia_ellipsoid(view, f, line_scale(in.frame_h), !in.close_up);
  add_invariable_plane(view, f);
  if (in.separatrix && !in.close_up) add_separatrix(view, f, in);
  add_motion(view, f, in);
  add_direct_labels(view, f, in);
}

}  // namespace tumble::viz
