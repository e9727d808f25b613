#include "viz/strip_chart.hpp"

#include "viz/surfaces.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/format.hpp"
#include "viz/palette.hpp"
#include "viz/text_layout.hpp"

namespace tumble::viz {

namespace {

// The chart's head: the series' key (names in their colours) top-right, a
// little below the view's top, or at its top when it fills the width; the
// view's title is the layout's (compose::plan_frame), above the view.
struct Head {
  float key_y = 0;      // top of the key row, px
  float key_px = 0;     // key text size
  float key_w = 0;      // key row width, px
  float top_px = 0;     // where the plot may start
};

Head head_layout(const StripChartInput& in, int width_px, float font_px) {
  Head h;
  const float f = font_px, w = static_cast<float>(width_px);
  const float title_px = in.frame_h > 0 ? text_px(TextRole::view_title, in.frame_h) : f;
  h.key_px = in.frame_h > 0 ? text_px(TextRole::key, in.frame_h) : f;
  for (const Series& s : in.series) h.key_w += text_width(s.name, h.key_px) + 1.2f * h.key_px;
  h.key_y = h.key_w + 2 * title_px < w ? 0.35f * title_px : 0.0f;
  // The plot starts below it, with room for the top value tick (half a tick above it).
  h.top_px = h.key_y + 1.3f * h.key_px + 0.7f * f;
  return h;
}

}  // namespace

ChartMap::ChartMap(const StripChartInput& in, int width_px, int height_px, float font_px)
    : t0_(in.t0), t1_(in.t1 > in.t0 ? in.t1 : in.t0 + 1), lo_(in.lo), hi_(in.hi > in.lo ? in.hi : in.lo + 1),
      aspect_(static_cast<double>(width_px) / std::max(height_px, 1)), w_(width_px), h_(height_px) {
  // Margins in pixels turned into world units (half height = 1 world unit).
  const double px = 2.0 / std::max(height_px, 1);
  x0_ = -aspect_ + 5.5 * font_px * px;
  x1_ = aspect_ - 1.2 * font_px * px;
  y0_ = -1 + 2.4 * font_px * px;
  y1_ = 1 - head_layout(in, width_px, static_cast<float>(font_px)).top_px * px;
}

glm::dvec3 ChartMap::at(double t, double v) const {
  return {x0_ + (x1_ - x0_) * (t - t0_) / (t1_ - t0_), y0_ + (y1_ - y0_) * (v - lo_) / (hi_ - lo_), 0.0};
}

glm::vec2 ChartMap::pixel(const glm::dvec3& p) const {
  return {static_cast<float>((p.x / aspect_ * 0.5 + 0.5) * w_), static_cast<float>((0.5 - p.y * 0.5) * h_)};
}

namespace {

// Slowed stretches: pale bands behind the curves (z < 0, the camera looks down -z), each labelled.
void add_slow_bands(View& view, const StripChartInput& in, const ChartMap& m, float font_px) {
  for (const StripChartInput::Band& band : in.shaded) {
    const double t0 = std::clamp(band.start, in.t0, in.t1), t1 = std::clamp(band.end, in.t0, in.t1);
    if (t1 <= t0) continue;
    const glm::dvec3 p0 = m.at(t0, in.lo), p1 = m.at(t1, in.hi);
    view.surfaces.push_back(rectangle({0.5 * (p0.x + p1.x), 0.5 * (p0.y + p1.y), -0.5},
                                      {0.5 * (p1.x - p0.x), 0, 0}, {0, 0.5 * (p1.y - p0.y), 0}, kSlowBandColor));
    const glm::vec2 at = m.pixel(m.at(t0, in.lo));
    view.texts.push_back({band.label, {at.x + 0.2f * font_px, at.y + 0.3f * font_px}, font_px, {0.2f, 0.3f, 0.6f, 1.0f}});
  }
}

// Frame, zero line, the series' curves, playhead.
void add_chart_lines(View& view, const StripChartInput& in, const ChartMap& m) {
  const Color ink = color_of(Meaning::ink), faint{0.55f, 0.57f, 0.62f, 0.6f};
  auto line = [&](std::vector<glm::dvec3> pts, Color c, float lw, const char* name) {
    view.polylines.push_back({std::move(pts), c, lw, false, name});
  };
  line({m.at(in.t0, in.lo), m.at(in.t1, in.lo), m.at(in.t1, in.hi), m.at(in.t0, in.hi), m.at(in.t0, in.lo)}, ink, 1.0f, "");
  if (in.lo < 0 && in.hi > 0) line({m.at(in.t0, 0), m.at(in.t1, 0)}, faint, 1.0f, "");
  for (const Series& s : in.series) {
    std::vector<glm::dvec3> pts;
    for (std::size_t i = 0; i < in.times.size() && i < s.values.size(); ++i)
      if (std::isfinite(s.values[i])) pts.push_back(m.at(in.times[i], std::clamp(s.values[i], in.lo, in.hi)));
    if (pts.size() >= 2) line(std::move(pts), s.color, 2.0f, "series");
  }
  line({m.at(in.playhead, in.lo), m.at(in.playhead, in.hi)}, {0.2f, 0.2f, 0.25f, 0.8f}, 1.5f, "playhead");
}

// Ticks (value range on the left, time range below), the series' key.
void add_chart_text(View& view, const StripChartInput& in, const ChartMap& m, const Head& head, float w, float f) {
  const Color ink = color_of(Meaning::ink);
  auto text = [&](const std::string& s, glm::vec2 p, Color c) {
    view.texts.push_back({s, p, f, c, "tick"});
  };
  const glm::vec2 top_left = m.pixel(m.at(in.t0, in.hi)), bottom_left = m.pixel(m.at(in.t0, in.lo));
  const glm::vec2 bottom_right = m.pixel(m.at(in.t1, in.lo));
  text(format_number(in.hi, 3), {4.0f, top_left.y - 0.5f * f}, ink);
  text(format_number(in.lo, 3), {4.0f, bottom_left.y - 0.5f * f}, ink);
  if (in.lo < 0 && in.hi > 0) {
    const float y0 = m.pixel(m.at(in.t0, 0)).y - 0.5f * f;
    // Only where it clears the range's ends.
    if (y0 > top_left.y + 0.5f * f && y0 + f < bottom_left.y - 0.5f * f) text("0", {4.0f, y0}, ink);
  }
  const std::string t1 = format_number(in.t1, 3) + " s";
  text(format_number(in.t0, 3) + " s", {bottom_left.x, bottom_left.y + 0.3f * f}, ink);
  text(t1, {right_aligned_x(t1, f, bottom_right.x), bottom_left.y + 0.3f * f}, ink);
  float x = w - head.key_w;
  for (const Series& s : in.series) {
    TextItem k{s.name, {x, head.key_y}, head.key_px, s.color, "key"};
    k.key = true;
    view.texts.push_back(std::move(k));
    x += text_width(s.name, head.key_px) + 1.2f * head.key_px;
  }
}

}  // namespace

void build_strip_chart(View& view, const StripChartInput& in, int width_px, int height_px, float font_px) {
  const Head head = head_layout(in, width_px, font_px);
  const ChartMap m(in, width_px, height_px, font_px);
  view.name = "plot";
  view.camera = Camera{};
  view.camera.position = {0, 0, 5};
  view.camera.target = {0, 0, 0};
  view.camera.up = {0, 1, 0};
  view.camera.ortho_half_height = 1;
  view.camera.near_m = 1;
  view.camera.far_m = 10;
  add_slow_bands(view, in, m, font_px);
  add_chart_lines(view, in, m);
  add_chart_text(view, in, m, head, static_cast<float>(width_px), font_px);
}

}  // namespace tumble::viz
