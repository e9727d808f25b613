#include "viz/strip_chart.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/format.hpp"

namespace tumble::viz {

ChartMap::ChartMap(const StripChartInput& in, int width_px, int height_px, float font_px)
    : t0_(in.t0), t1_(in.t1 > in.t0 ? in.t1 : in.t0 + 1), lo_(in.lo), hi_(in.hi > in.lo ? in.hi : in.lo + 1),
      aspect_(static_cast<double>(width_px) / std::max(height_px, 1)), w_(width_px), h_(height_px) {
  // Margins in pixels turned into world units (half height = 1 world unit).
  const double px = 2.0 / std::max(height_px, 1);
  x0_ = -aspect_ + 5.5 * font_px * px;
  x1_ = aspect_ - 1.2 * font_px * px;
  y0_ = -1 + 2.4 * font_px * px;
  y1_ = 1 - 2.6 * font_px * px;
}

glm::dvec3 ChartMap::at(double t, double v) const {
  return {x0_ + (x1_ - x0_) * (t - t0_) / (t1_ - t0_), y0_ + (y1_ - y0_) * (v - lo_) / (hi_ - lo_), 0.0};
}

glm::vec2 ChartMap::pixel(const glm::dvec3& p) const {
  return {static_cast<float>((p.x / aspect_ * 0.5 + 0.5) * w_), static_cast<float>((0.5 - p.y * 0.5) * h_)};
}

void build_strip_chart(View& view, const StripChartInput& in, int width_px, int height_px, float font_px) {
  const ChartMap m(in, width_px, height_px, font_px);
  view.camera = Camera{};
  view.camera.position = {0, 0, 5};
  view.camera.target = {0, 0, 0};
  view.camera.up = {0, 1, 0};
  view.camera.ortho_half_height = 1;
  view.camera.near_m = 1;
  view.camera.far_m = 10;
  const Color ink{0.12f, 0.13f, 0.16f, 1.0f}, faint{0.55f, 0.57f, 0.62f, 0.6f};
  auto line = [&](std::vector<glm::dvec3> pts, Color c, float w) {
    view.polylines.push_back({std::move(pts), c, w, false});
  };
  // Frame, zero line, playhead.
  line({m.at(in.t0, in.lo), m.at(in.t1, in.lo), m.at(in.t1, in.hi), m.at(in.t0, in.hi), m.at(in.t0, in.lo)}, ink, 1.0f);
  if (in.lo < 0 && in.hi > 0) line({m.at(in.t0, 0), m.at(in.t1, 0)}, faint, 1.0f);
  for (const Series& s : in.series) {
    std::vector<glm::dvec3> pts;
    for (std::size_t i = 0; i < in.times.size() && i < s.values.size(); ++i)
      if (std::isfinite(s.values[i])) pts.push_back(m.at(in.times[i], std::clamp(s.values[i], in.lo, in.hi)));
    if (pts.size() >= 2) line(std::move(pts), s.color, 2.0f);
  }
  line({m.at(in.playhead, in.lo), m.at(in.playhead, in.hi)}, {0.2f, 0.2f, 0.25f, 0.8f}, 1.5f);
  // Labels: value range on the left, time range below, series names on top.
  const float f = font_px;
  auto text = [&](const std::string& s, glm::vec2 p, Color c) { view.texts.push_back({s, p, f, c}); };
  const glm::vec2 top_left = m.pixel(m.at(in.t0, in.hi)), bottom_left = m.pixel(m.at(in.t0, in.lo));
  const glm::vec2 bottom_right = m.pixel(m.at(in.t1, in.lo));
  text(format_number(in.hi, 3), {4.0f, top_left.y - 0.5f * f}, ink);
  text(format_number(in.lo, 3), {4.0f, bottom_left.y - 0.5f * f}, ink);
  if (in.lo < 0 && in.hi > 0) text("0", {4.0f, m.pixel(m.at(in.t0, 0)).y - 0.5f * f}, ink);
  text(format_number(in.t0, 3) + " s", {bottom_left.x, bottom_left.y + 0.3f * f}, ink);
  text(format_number(in.t1, 3) + " s", {bottom_right.x - 3.0f * f, bottom_left.y + 0.3f * f}, ink);
  float x = top_left.x;
  if (!in.title.empty()) {
    text(in.title, {x, 0.3f * f}, ink);
    x += (static_cast<float>(in.title.size()) + 2) * 0.55f * f;
  }
  for (const Series& s : in.series) {
    text(s.name, {x, 0.3f * f}, s.color);
    x += (static_cast<float>(s.name.size()) + 2) * 0.55f * f;
  }
}

}  // namespace tumble::viz
