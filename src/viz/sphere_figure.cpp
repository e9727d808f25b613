#include "viz/sphere_figure.hpp"

#include <algorithm>
#include <cmath>

#include "viz/captions.hpp"
#include "viz/momentum_sphere.hpp"
#include "viz/palette.hpp"
#include "viz/scene_view.hpp"
#include "viz/sphere_camera.hpp"
#include "viz/text_layout.hpp"

namespace tumble::viz {

namespace {

void refine(const std::function<Eigen::Vector3d(double)>& at, double t0, const Eigen::Vector3d& p0, double t1,
            const Eigen::Vector3d& p1, double tol, int depth, std::vector<double>& out) {
  const double tm = 0.5 * (t0 + t1);
  const Eigen::Vector3d pm = at(tm);
  if (depth < 10 && ((pm - 0.5 * (p0 + p1)).norm() > tol || (p1 - p0).norm() > 30 * tol)) {
    refine(at, t0, p0, tm, pm, tol, depth + 1, out);
    refine(at, tm, pm, t1, p1, tol, depth + 1, out);
    return;
  }
  out.push_back(t1);
}

// The faint look of what lies behind the ball: a third of the colour's opacity.
Color faint(Color c) {
  c.a *= 0.32f;
  return c;
}


// Where the eye's ray towards p first meets the sphere of radius r (p itself when it misses).
glm::dvec3 near_side(const glm::dvec3& eye, const glm::dvec3& p, double r) {
  const glm::dvec3 d = p - eye;
  const double a = glm::dot(d, d), b = 2 * glm::dot(eye, d), c = glm::dot(eye, eye) - r * r;
  const double disc = b * b - 4 * a * c;
  if (a <= 0 || disc < 0) return p;
  return eye + ((-b - std::sqrt(disc)) / (2 * a)) * d;
}

}  // namespace

std::vector<double> refined_params(const std::function<Eigen::Vector3d(double)>& at, const std::vector<double>& params,
                                   double tolerance) {
  std::vector<double> out;
  if (params.empty()) return out;
  out.push_back(params[0]);
  Eigen::Vector3d prev = at(params[0]);
  for (std::size_t i = 1; i < params.size(); ++i) {
    const Eigen::Vector3d next = at(params[i]);
    refine(at, params[i - 1], prev, params[i], next, tolerance, 0, out);
    prev = next;
  }
  return out;
}

std::vector<Eigen::Vector3d> refined_curve(const std::function<Eigen::Vector3d(double)>& at,
                                           const std::vector<double>& params, double tolerance) {
  std::vector<Eigen::Vector3d> out;
  for (double t : refined_params(at, params, tolerance)) out.push_back(at(t));
  return out;
}

namespace {

// Whether `box` lies on one of the six half-axes as `project` draws them (the
// + arrows thickened by their heads' `head_px`); `curves`: or on a named curve
// (one a viewer follows), counting only what the ball does not hide, so that
// a name may sit over what is behind the ball (a figure that hides its back).
bool on_a_line(const View& view, const ViewportProjection& project, const Box& box, float head_px, bool curves) {
  const glm::dvec3 eye = view.camera.position;
  const auto on = [&](glm::vec2 p, float r) { return p.x + r > box.x0 && p.x - r < box.x1 && p.y + r > box.y0 && p.y - r < box.y1; };
  glm::vec2 base, tip;
  if (!project(glm::dvec3(0), base)) return false;
  for (int i = 0; i < 3; ++i)
    for (int sign : {1, -1}) {
      glm::dvec3 e(0);
      e[i] = sign * kAxisReach;
      if (!project(e, tip)) continue;
      for (int s = 0; s <= 24; ++s) {
        if (curves && hidden_by_ball(eye, e * (s / 24.0), 1.0)) continue;
        if (on(base + (tip - base) * (static_cast<float>(s) / 24), s == 24 && sign > 0 ? head_px + 1 : 2.5f)) return true;
      }
    }
  if (!curves) return false;
  const auto seen_on = [&](const glm::dvec3& x) {
    glm::vec2 p;
    return !hidden_by_ball(eye, x, 1.0) && project(x, p) && on(p, 2.5f);
  };
  for (const PolylineItem& l : view.polylines)
    if (!l.name.empty())
      for (std::size_t j = 0; j < l.points.size(); ++j)
        if (seen_on(l.points[j]) || (j > 0 && seen_on(0.5 * (l.points[j - 1] + l.points[j])))) return true;
  return false;
}

// Whether `box` overlaps a text of `view` (a name already placed).
bool on_a_name(const View& view, const Box& box) {
  return std::any_of(view.texts.begin(), view.texts.end(), [&](const TextItem& t) { return text_box(t).overlaps(box); });
}

}  // namespace

void add_sphere_axes(View& view, float width_px, float height_px, float label_px) {
  add_sphere_axis_lines(view);
  name_sphere_axes(view, width_px, height_px, label_px);
}

void add_sphere_axis_lines(View& view) {
  for (int i = 0; i < 3; ++i) {
    glm::dvec3 e(0);
    e[i] = kAxisReach;
    // A + end the ball hides is not drawn (nothing of it would show) and not named.
    if (!hidden_by_ball(view.camera.position, e, 1.0))
      view.arrows.push_back({{0, 0, 0}, e, 0.012, kAxisColors[i], std::string("axis") + char('1' + i)});
    view.polylines.push_back({{glm::dvec3(0), -e}, color_of(static_cast<Meaning>(i), 0.75f), 2.0f, false});
  }
}

namespace {

// What every axis end's name is placed against: the view as named so far, its
// projection, the arrowheads' size and the ball as drawn.
struct AxisNaming {
  const View& view;
  const ViewportProjection& project;
  float width_px, height_px, label_px, head_px;
  bool clear_of_curves;
  glm::vec2 centre;
  float ball_px;
  bool on_face(const Box& b) const {
    const glm::vec2 near{std::clamp(centre.x, b.x0, b.x1), std::clamp(centre.y, b.y0, b.y1)};
    return glm::length(near - centre) < ball_px;
  }
};

// One end's name beside its tip (at `tip`, the centre at `base`), `past` px beyond it.
TextItem name_axis_end(const AxisNaming& n, const char* text, Color color, glm::vec2 tip, glm::vec2 base, float past) {
  TextItem t{text, {0, 0}, n.label_px, color};
  const InkSpan ink = text_ink(t.text, n.label_px);
  const glm::vec2 along = tip - base;
  const float len = glm::length(along);
  // Seen end-on (pointing at the viewer): beside its tip, up and right; the
  // shorter the axis as drawn, the more its label leans that way, so that a
  // turning camera moves it smoothly, never by a jump.
  const glm::vec2 end_on(0.7071f, -0.7071f);
  const float lean = std::clamp(len / (1.5f * n.label_px), 0.0f, 1.0f);
  const glm::vec2 mixed = len > 0 ? (1 - lean) * end_on + lean * (along / len) : end_on;
  const glm::vec2 d0 = glm::length(mixed) > 0.2f ? glm::normalize(mixed) : (len > 0 ? along / len : end_on);
  // An end seen beside the ball is named beside it too: on its face, a name reads as a point there.
  const bool off_face = len > n.ball_px;
  // Along the axis as drawn, else turned a little at a time until clear of the axes and inside the view;
  // where no turn is, along the axis pushed back inside (a narrow view, an axis along its edge).
  auto at = [&](float turn, bool curves = true) {
    const glm::vec2 d{d0.x * std::cos(turn) - d0.y * std::sin(turn), d0.x * std::sin(turn) + d0.y * std::cos(turn)};
    const float reach = past + 0.5f * (std::abs(d.x) * ink.width() + std::abs(d.y) * n.label_px) + 0.25f * n.label_px;
    const glm::vec2 centre = tip + reach * d;
    t.position_px = {centred_x(t.text, n.label_px, centre.x), centre.y - 0.5f * n.label_px};
    const Box b = text_box(t);
    // Among curves, a quarter line clear (as the labels' later settling keeps them, which would move it).
    const float g = n.clear_of_curves ? 0.25f * n.label_px : 0.0f;
    const Box wide{b.x0 - g, b.y0 - g, b.x1 + g, b.y1 + g};
    return b.x0 >= 0 && b.y0 >= 0 && b.x1 <= n.width_px && b.y1 <= n.height_px &&
           !on_a_line(n.view, n.project, wide, n.head_px, n.clear_of_curves && curves) &&
           !(n.clear_of_curves && ((off_face && n.on_face(b)) || on_a_name(n.view, wide)));
  };
  bool placed = false;
  for (const float turn : {0.0f, 0.45f, -0.45f, 0.9f, -0.9f, 1.35f, -1.35f, 1.8f, -1.8f, 2.4f, -2.4f})
    if ((placed = at(turn))) break;
  // Among the curves near a tip (a small sphere), finer turns; then over a curve, off the face.
  for (int k = 0; n.clear_of_curves && !placed && k < 66; ++k)
    placed = at(0.15f * static_cast<float>((k % 33 + 1) / 2) * (k % 2 ? -1.0f : 1.0f), k < 33);
  if (!placed) {
    at(0.0f);
    const Box b = text_box(t);
    t.position_px.x += std::max(0.0f, -b.x0) - std::max(0.0f, b.x1 - n.width_px);
    t.position_px.y += std::max(0.0f, -b.y0) - std::max(0.0f, b.y1 - n.height_px);
  }
  return t;
}

}  // namespace

std::optional<glm::vec3> ball_on_screen(const Camera& camera, float width_px, float height_px) {
  const ViewportProjection project(camera, width_px, height_px);
  glm::vec2 centre, rim;
  if (!project(glm::dvec3(0), centre) || !project(glm::normalize(camera.up), rim)) return std::nullopt;
  return glm::vec3(centre, glm::length(rim - centre));
}

void name_sphere_axes(View& view, float width_px, float height_px, float label_px, bool clear_of_curves) {
  static const char* const kPlus[3] = {"e\u2081", "e\u2082", "e\u2083"};               // e₁ e₂ e₃
  static const char* const kMinus[3] = {"\u2212e\u2081", "\u2212e\u2082", "\u2212e\u2083"};  // −e₁ −e₂ −e₃
  const ViewportProjection project(view.camera, width_px, height_px);
  float head_px = 0;
  for (int i = 0; i < 3; ++i) {
    glm::dvec3 e(0);
    e[i] = kAxisReach;
    glm::vec2 tip, head;
    if (project(e, tip) && project(e + 0.029 * glm::normalize(view.camera.up), head))
      head_px = std::max(head_px, glm::length(head - tip));
  }
  const glm::vec3 ball = ball_on_screen(view.camera, width_px, height_px).value_or(glm::vec3(0));
  const AxisNaming naming{view, project, width_px, height_px, label_px, head_px, clear_of_curves, glm::vec2(ball), ball.z};
  for (int i = 0; i < 3; ++i)
    for (int sign : {1, -1}) {
      glm::dvec3 end(0);
      end[i] = sign * kAxisReach;
      glm::vec2 tip, base;
      if (!project(end, tip) || !project(glm::dvec3(0), base)) continue;
      // Each end is named at its own tip; an end the ball hides (pointing away) is not named: nothing of it shows.
      if (hidden_by_ball(view.camera.position, end, 1.0)) continue;
      TextItem t = name_axis_end(naming, sign > 0 ? kPlus[i] : kMinus[i], kAxisColors[i], tip, base, sign > 0 ? head_px : 1.0f);
      t.name = std::string(sign > 0 ? "axis_label_e" : "axis_label_-e") + char('1' + i);
      view.texts.push_back(std::move(t));
    }
}

void add_saddles(View& view) {
  const Color ring = color_of(Meaning::separatrix);
  for (int sign : {1, -1}) {
    // A white dot in a sky-blue ring: where the two separatrix circles cross
    // (Π, dark and larger, stands out on it when it passes).
    view.points.push_back({{0, sign * 1.0, 0}, 0.05, ring, sign > 0 ? "saddle_+e2" : "saddle_-e2"});
    view.points.push_back({{0, sign * 1.02, 0}, 0.028, {1.0f, 1.0f, 1.0f, 1.0f}, ""});
  }
}

void add_direction_arrows(View& view, const std::vector<Eigen::Vector3d>& curve, const Eigen::Vector3d& inertia,
                          int count, Color color, double size) {
  if (curve.size() < 3 || count <= 0) return;
  std::vector<double> along{0};
  for (std::size_t i = 1; i < curve.size(); ++i) along.push_back(along.back() + (curve[i] - curve[i - 1]).norm());
  const double total = along.back();
  if (total <= 0) return;
  std::size_t j = 0;
  for (int k = 0; k < count; ++k) {
    const double s = total * (k + 0.5) / count;
    while (j + 1 < along.size() && along[j + 1] < s) ++j;
    const Eigen::Vector3d p = curve[j];
    const Eigen::Vector3d v = p.cross(p.cwiseQuotient(inertia));  // dΠ/dt = Π × ω, up to |L|'s scale
    // Only where the curve faces the eye: an arrow near the rim is a fragment.
    const glm::dvec3 eye = glm::normalize(view.camera.position - view.camera.target);
    if (v.norm() <= 0 || hidden_by_ball(view.camera.position, to_glm(p), 1.0) || glm::dot(eye, to_glm(p.normalized())) < 0.35)
      continue;
    const glm::dvec3 dir = to_glm(v.normalized());
    view.arrows.push_back({to_glm(p) - 0.5 * size * dir, size * dir, 0.12 * size, color, ""});
  }
}

Color faint_marker(Color c) {
  // Points are drawn opaque (lit balls, no blending): two thirds of the ball's colour instead of a third of the opacity.
  return {glm::mix(glm::vec3(c), glm::vec3(kSphereBallColor), 0.68f), 1.0f};
}

void show_far_side(View& view, std::size_t first_polyline, double ball, bool hide) {
  const glm::dvec3 eye = view.camera.position;
  const double front = 1.0 + 0.5 * (1.0 - ball);  // above the ball, below nothing on the sphere
  std::vector<PolylineItem> out(view.polylines.begin(), view.polylines.begin() + static_cast<long>(first_polyline));
  for (std::size_t i = first_polyline; i < view.polylines.size(); ++i) {
    const PolylineItem& p = view.polylines[i];
    // Runs of points on one side; a run's last point is the next run's first, so the line stays whole.
    std::size_t start = 0;
    while (start + 1 < p.points.size()) {
      const bool hidden = hidden_by_ball(eye, p.points[start], ball);
      std::size_t end = start + 1;
      while (end + 1 < p.points.size() && hidden_by_ball(eye, p.points[end], ball) == hidden) ++end;
      // The separatrix's back half is not drawn: seen through the ball it reads as a ring round the near pole.
      if (hidden && (hide || p.name == "separatrix")) {
        start = end;
        continue;
      }
      PolylineItem run{{}, hidden ? faint(p.color) : p.color, hidden ? 0.75f * p.width_px : p.width_px, p.fade,
                       hidden ? "" : p.name};
      for (std::size_t j = start; j <= end; ++j)
        run.points.push_back(hidden ? near_side(eye, p.points[j], front) : p.points[j]);
      out.push_back(std::move(run));
      start = end;
    }
  }
  view.polylines = std::move(out);
  // Every marker on the sphere (not the ball itself, at the centre): a saddle's white core too.
  const auto behind = [&](const PointItem& pt) { return glm::length(pt.position) > 0.5 && hidden_by_ball(eye, pt.position, ball); };
  if (hide) std::erase_if(view.points, behind);
  for (PointItem& pt : view.points)
    if (behind(pt)) {
      pt.position = near_side(eye, pt.position, front + pt.radius);
      pt.color = faint_marker(pt.color);
      pt.radius *= 0.8;
    }
}

}  // namespace tumble::viz
