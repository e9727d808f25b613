#include "viz/sphere_figure.hpp"

#include <algorithm>
#include <cmath>

#include "viz/captions.hpp"
#include "viz/palette.hpp"
#include "viz/scene_view.hpp"
#include "viz/sphere_camera.hpp"
#include "viz/text_layout.hpp"

namespace tumble::viz {

namespace {

glm::dvec3 g(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

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

void add_sphere_axes(View& view, float width_px, float height_px, float label_px) {
  static const char* const kPlus[3] = {"e\u2081", "e\u2082", "e\u2083"};               // e₁ e₂ e₃
  static const char* const kMinus[3] = {"\u2212e\u2081", "\u2212e\u2082", "\u2212e\u2083"};  // −e₁ −e₂ −e₃
  const ViewportProjection project(view.camera, width_px, height_px);
  for (int i = 0; i < 3; ++i) {
    glm::dvec3 e(0);
    e[i] = kAxisReach;
    view.arrows.push_back({{0, 0, 0}, e, 0.012, kAxisColors[i], std::string("axis") + char('1' + i)});
    view.polylines.push_back({{glm::dvec3(0), -e}, color_of(static_cast<Meaning>(i), 0.75f), 2.0f, false});
    for (int sign : {1, -1}) {
      const glm::dvec3 tip = e * (sign * kAxisLabelReach / kAxisReach);
      glm::vec2 px;
      if (hidden_by_ball(view.camera.position, tip, 1.0) || !project(tip, px)) continue;
      TextItem t{sign > 0 ? kPlus[i] : kMinus[i], {0, 0}, label_px, kAxisColors[i]};
      t.position_px = {centred_x(t.text, label_px, px.x), px.y - 0.5f * label_px};
      const Box b = text_box(t);
      if (b.x0 < 0 || b.y0 < 0 || b.x1 > width_px || b.y1 > height_px)
        continue;  // out of the view: the other end is in it
      t.name = std::string(sign > 0 ? "axis_label_e" : "axis_label_-e") + char('1' + i);
      view.texts.push_back(std::move(t));
    }
  }
}

void add_saddles(View& view) {
  const Color ring = color_of(Meaning::separatrix);
  for (int sign : {1, -1}) {
    // A dark dot in a sky-blue ring: where the two separatrix circles cross.
    view.points.push_back({{0, sign * 1.0, 0}, 0.05, ring, sign > 0 ? "saddle_+e2" : "saddle_-e2"});
    view.points.push_back({{0, sign * 1.02, 0}, 0.026, color_of(Meaning::ink), ""});
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
    if (v.norm() <= 0 || hidden_by_ball(view.camera.position, g(p), 1.0)) continue;
    const glm::dvec3 dir = g(v.normalized());
    view.arrows.push_back({g(p) - 0.5 * size * dir, size * dir, 0.12 * size, color, ""});
  }
}

void show_far_side(View& view, std::size_t first_polyline, double ball) {
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
      PolylineItem run{{}, hidden ? faint(p.color) : p.color, hidden ? 0.75f * p.width_px : p.width_px, p.fade,
                       hidden ? "" : p.name};
      for (std::size_t j = start; j <= end; ++j)
        run.points.push_back(hidden ? near_side(eye, p.points[j], front) : p.points[j]);
      out.push_back(std::move(run));
      start = end;
    }
  }
  view.polylines = std::move(out);
  for (PointItem& pt : view.points)
    if (!pt.name.empty() && hidden_by_ball(eye, pt.position, ball)) {
      pt.position = near_side(eye, pt.position, front + pt.radius);
      pt.color = faint(pt.color);
      pt.radius *= 0.8;
    }
}

}  // namespace tumble::viz
