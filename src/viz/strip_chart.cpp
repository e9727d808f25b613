#include "viz/strip_chart.hpp"

#include "viz/surfaces.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "base/format.hpp"
#include "viz/palette.hpp"
#include "viz/text_layout.hpp"

namespace tumble::viz {

namespace {

// The key's names of the shaded bands: "■ ×1/8 slow motion", once per speed.
std::vector<std::string> band_names(const StripChartInput& in) {
  std::vector<std::string> out;
  for (const StripChartInput::Band& b : in.shaded) {
    const std::string n = "\u25a0 " + b.label + (b.label.find('/') != std::string::npos ? " slow motion" : " fast");
    if (std::find(out.begin(), out.end(), n) == out.end()) out.push_back(n);
  }
  return out;
}

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
  const float title_px = in.frame_h > 0 ? text_px(TextRole::view_title, in.frame_h, in.text_scale) : f;
  h.key_px = in.frame_h > 0 ? text_px(TextRole::key, in.frame_h, in.text_scale) : f;
  if (!in.direct_labels)
    for (const Series& s : in.series) h.key_w += text_width(s.name, h.key_px) + 1.2f * h.key_px;
  for (const std::string& b : band_names(in)) h.key_w += text_width(b, h.key_px) + 1.2f * h.key_px;
  h.key_y = h.key_w > 0 && h.key_w + 2 * title_px < w ? 0.35f * title_px : 0.0f;
  // The plot starts below it, with room for the top value tick (half a tick above it).
  h.top_px = h.key_w > 0 ? h.key_y + 1.3f * h.key_px + 0.7f * f : 0.7f * f;
  return h;
}

}  // namespace

ChartMap::ChartMap(const StripChartInput& in, int width_px, int height_px, float font_px)
    : t0_(in.t0), t1_(in.t1 > in.t0 ? in.t1 : in.t0 + 1), lo_(in.lo), hi_(in.hi > in.lo ? in.hi : in.lo + 1),
      aspect_(static_cast<double>(width_px) / std::max(height_px, 1)), w_(width_px), h_(height_px) {
  // Margins in pixels turned into world units (half height = 1 world unit).
  const double px = 2.0 / std::max(height_px, 1);
  x0_ = -aspect_ + 5.5 * font_px * px;
  double labels = 0;  // the widest head label, its gap from the playhead and a margin, px
  if (in.direct_labels)
    for (const Series& s : in.series) labels = std::max(labels, double(text_width(s.name, font_px)) + 0.9 * font_px);
  x1_ = aspect_ - std::max(1.2 * font_px, labels) * px;
  y0_ = -1 + 2.4 * font_px * px;
  y1_ = 1 - head_layout(in, width_px, static_cast<float>(font_px)).top_px * px;
}

glm::dvec3 ChartMap::at(double t, double v) const {
  return {x0_ + (x1_ - x0_) * (t - t0_) / (t1_ - t0_), y0_ + (y1_ - y0_) * (v - lo_) / (hi_ - lo_), 0.0};
}

glm::vec2 ChartMap::pixel(const glm::dvec3& p) const {
  return {static_cast<float>((p.x / aspect_ * 0.5 + 0.5) * w_), static_cast<float>((0.5 - p.y * 0.5) * h_)};
}

double ChartMap::value_at(float pixel_y) const {
  const double y = 1 - 2.0 * pixel_y / std::max(h_, 1);
  return lo_ + (hi_ - lo_) * (y - y0_) / (y1_ - y0_);
}

// A fraction in per cent, signed: "+120 %", "0", "−10 %".
std::string percent_text(double v) {
  const double p = 100 * v;
  if (std::abs(p) < 0.5) return "0";
  return (p > 0 ? "+" : "\u2212") + std::to_string(std::lround(std::abs(p))) + " %";
}

namespace {

// A time tick's step: 1, 2 or 5 times a power of ten, about six across.
double time_step(double span) {
  const double rough = std::max(span, 1e-9) / 6, decade = std::pow(10.0, std::floor(std::log10(rough)));
  return rough >= 5 * decade ? 5 * decade : rough >= 2 * decade ? 2 * decade : decade;
}

// Slowed stretches: pale bands behind the curves (z < 0, the camera looks down -z), each labelled.
void add_slow_bands(View& view, const StripChartInput& in, const ChartMap& m, float font_px) {
  for (const StripChartInput::Band& band : in.shaded) {
    const double t0 = std::clamp(band.start, in.t0, in.t1), t1 = std::clamp(band.end, in.t0, in.t1);
    if (t1 <= t0) continue;
    const glm::dvec3 p0 = m.at(t0, in.lo), p1 = m.at(t1, in.hi);
    view.surfaces.push_back(rectangle({0.5 * (p0.x + p1.x), 0.5 * (p0.y + p1.y), -0.5},
                                      {0.5 * (p1.x - p0.x), 0, 0}, {0, 0.5 * (p1.y - p0.y), 0}, kSlowBandColor));
    (void)font_px;  // the bands are named in the chart's key, not under the axis (where a name reads as a tick)
  }
}

// Notes inside the chart (a level's, a point's) smaller than the ticks: they sit among the curves, and
// a level near the top border needs its note to fit between the two.
constexpr float kNoteScale = 0.7f;

// Each level's note along its dashed line, inside the chart: above it at the
// right end (rising curves have passed it there), or under a line too close
// to the top border for that, at the left end (where they have not reached it yet).
std::vector<TextItem> level_notes(const StripChartInput& in, const ChartMap& m, float f) {
  const float left = m.pixel(m.at(in.t0, in.lo)).x, right = m.pixel(m.at(in.t1, in.lo)).x;
  const float top = m.pixel(m.at(in.t0, in.hi)).y;
  const float s = kNoteScale * f;
  std::vector<TextItem> out;
  for (const StripChartInput::Level& l : in.levels) {
    if (l.note.empty() || l.value < in.lo || l.value > in.hi) continue;
    const float y = m.pixel(m.at(in.t0, l.value)).y;
    const glm::vec2 at = y - 1.3f * s > top ? glm::vec2{right - 0.3f * f - text_width(l.note, s), y - 1.15f * s}
                                            : glm::vec2{left + 0.3f * f, y + 0.15f * s};
    out.push_back({l.note, at, s, kLevelColor, "level_note"});
  }
  return out;
}

// A vertical line at t across the chart (a flip's mark, the playhead), broken
// where a level's note stands: the playhead sweeps through the notes and the
// flips' marks lie under them, and a line through a word strikes it out.
void add_vertical(View& view, const StripChartInput& in, const ChartMap& m, double t, Color c, float lw,
                  const char* name, const std::vector<TextItem>& notes, float f) {
  const float x = m.pixel(m.at(t, in.lo)).x, pad = std::max(2.5f, 0.2f * f);
  std::vector<std::pair<double, double>> gaps;  // value ranges the line leaves out, lo..hi
  for (const TextItem& n : notes) {
    const Box b = text_box(n);
    if (x + pad > b.x0 && x - pad < b.x1) gaps.push_back({m.value_at(b.y1 + pad), m.value_at(b.y0 - pad)});
  }
  std::sort(gaps.begin(), gaps.end());
  double from = in.lo;
  for (const auto& [g0, g1] : gaps) {
    if (g0 > from) view.polylines.push_back({{m.at(t, from), m.at(t, std::min(g0, in.hi))}, c, lw, false, name});
    from = std::max(from, g1);
  }
  if (from < in.hi) view.polylines.push_back({{m.at(t, from), m.at(t, in.hi)}, c, lw, false, name});
}

// Frame, zero line, the series' curves, playhead (f: the ticks' text size, for the notes).
void add_chart_lines(View& view, const StripChartInput& in, const ChartMap& m, float f) {
  const std::vector<TextItem> notes = level_notes(in, m, f);
  const Color ink = color_of(Meaning::ink), faint{0.55f, 0.57f, 0.62f, 0.6f};
  auto line = [&](std::vector<glm::dvec3> pts, Color c, float lw, const char* name) {
    view.polylines.push_back({std::move(pts), c, lw, false, name});
  };
  line({m.at(in.t0, in.lo), m.at(in.t1, in.lo), m.at(in.t1, in.hi), m.at(in.t0, in.hi), m.at(in.t0, in.lo)}, ink, 1.0f, "");
  if (in.lo < 0 && in.hi > 0) line({m.at(in.t0, 0), m.at(in.t1, 0)}, faint, 1.0f, "");
  // Faint gridlines at the time ticks.
  const double step = time_step(in.t1 - in.t0);
  for (double t = std::ceil(in.t0 / step + 1e-9) * step; t < in.t1 - 1e-9; t += step)
    line({m.at(t, in.lo), m.at(t, in.hi)}, {0.55f, 0.57f, 0.62f, 0.3f}, 1.0f, "");
  if (in.log10)  // and at the decades
    for (int d = static_cast<int>(std::ceil(in.lo - 1e-9)); d <= in.hi + 1e-9; ++d)
      line({m.at(in.t0, d), m.at(in.t1, d)}, {0.55f, 0.57f, 0.62f, 0.3f}, 1.0f, "");
  for (const StripChartInput::Level& l : in.levels)  // dashed: about 40 dashes across
    if (l.value >= in.lo && l.value <= in.hi)
      for (int i = 0; i < 40; ++i) {
        const double t = in.t0 + (in.t1 - in.t0) * i / 40.0;
        line({m.at(t, l.value), m.at(t + 0.6 * (in.t1 - in.t0) / 40.0, l.value)}, kLevelColor, 2.0f, "");
      }
  for (double t : in.marks)  // under the curves, thin, grey: no method's colour (explicit Euler's is a red)
    if (t >= in.t0 && t <= std::min(in.t1, in.playhead)) add_vertical(view, in, m, t, {0.35f, 0.36f, 0.40f, 0.6f}, 1.5f, "mark", notes, f);
  for (const Series& s : in.series) {
    std::vector<glm::dvec3> pts;
    for (std::size_t i = 0; i < in.times.size() && i < s.values.size(); ++i)
      if (std::isfinite(s.values[i])) pts.push_back(m.at(in.times[i], std::clamp(s.values[i], in.lo, in.hi)));
    if (pts.size() >= 2) line(std::move(pts), s.color, 3.0f, "series");
  }
  add_vertical(view, in, m, in.playhead, {0.2f, 0.2f, 0.25f, 0.8f}, 1.5f, "playhead", notes, f);
}

// "10⁻⁸": a decade written as a power of ten.
std::string decade(int d) {
  static const char* const kSup[10] = {"\u2070", "\u00b9", "\u00b2", "\u00b3", "\u2074",
                                       "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
  std::string out = d < 0 ? "10\u207b" : "10";
  const std::string digits = std::to_string(std::abs(d));
  for (char c : digits) out += kSup[c - '0'];
  return out;
}

// Does a value tick at `y` (px, its top) keep clear of every level's name?
bool clear_of_levels(const StripChartInput& in, const ChartMap& m, float y, float f) {
  for (const StripChartInput::Level& l : in.levels)
    if (!l.label.empty() && l.value >= in.lo && l.value <= in.hi && std::abs(m.pixel(m.at(in.t0, l.value)).y - 0.5f * f - y) < 1.1f * f)
      return false;
  return true;
}

// A log axis: its decades named on the left (at most about six, evenly
// spaced, apart; add_chart_lines draws a faint gridline at each decade).
void add_decade_ticks(View& view, const StripChartInput& in, const ChartMap& m, float f) {
  const int first = static_cast<int>(std::ceil(in.lo - 1e-9)), last = static_cast<int>(std::floor(in.hi + 1e-9));
  // Every n-th decade, so that names keep a tenth of a line apart (a value
  // read off the axis needs names close together more than it needs air).
  const float per_decade = std::abs(m.pixel(m.at(in.t0, 0)).y - m.pixel(m.at(in.t0, 1)).y);
  const int step = std::max({1, (last - first + 5) / 6, static_cast<int>(std::ceil(1.1f * f / std::max(per_decade, 1e-3f)))});
  // Counted from 10⁰ where the axis holds it (a reader's anchor), else from the floor.
  const int anchor = first <= 0 && last >= 0 ? 0 : first;
  for (int d = first; d <= last; ++d) {
    if (((d - anchor) % step + step) % step != 0) continue;
    const float y = m.pixel(m.at(in.t0, d)).y;
    if (clear_of_levels(in, m, y - 0.5f * f, f))
      view.texts.push_back({decade(d), {4.0f, y - 0.5f * f}, f, color_of(Meaning::ink), "tick"});
  }
}

// Each curve named at its head (its last point drawn), in its colour; names
// that would touch are pushed apart. They stack in the order of each curve's
// highest value so far, not of its head, so that a curve dipping under
// another for a moment (a signed error crossing zero on a log scale) does not
// make the two names swap places.
void add_head_labels(View& view, const StripChartInput& in, const ChartMap& m, float f) {
  struct Head {
    float y;
    std::size_t series;
    glm::vec2 at;
    double highest;
  };
  std::vector<Head> heads;
  for (std::size_t i = 0; i < in.series.size(); ++i) {
    const Series& s = in.series[i];
    const std::size_t n = std::min(in.times.size(), s.values.size());
    double highest = -1e300;
    for (std::size_t j = 0; j < n; ++j)
      if (std::isfinite(s.values[j])) highest = std::max(highest, std::min(s.values[j], in.hi));
    for (std::size_t j = n; j-- > 0;)
      if (std::isfinite(s.values[j])) {
        const glm::vec2 p = m.pixel(m.at(in.times[j], std::clamp(s.values[j], in.lo, in.hi)));
        heads.push_back({p.y - 0.5f * f, i, p, highest});
        break;
      }
  }
  std::stable_sort(heads.begin(), heads.end(), [](const Head& a, const Head& b) { return a.highest > b.highest; });
  // Inside the chart's box: under its top border, over its bottom one.
  const float top = m.pixel(m.at(in.t0, in.hi)).y + 0.15f * f, bottom = m.pixel(m.at(in.t0, in.lo)).y - 1.2f * f;
  for (std::size_t i = 0; i < heads.size(); ++i) {
    // Off a reference level's dashed line: just above it (a name struck
    // through reads as crossed out); the names above it then make way upwards.
    bool on_level = false;
    for (const StripChartInput::Level& l : in.levels) {
      const float ly = m.pixel(m.at(in.t0, l.value)).y;
      if (l.value >= in.lo && l.value <= in.hi && heads[i].y < ly + 0.1f * f && heads[i].y + f > ly - 0.1f * f)
        heads[i].y = ly - 1.1f * f, on_level = true;
    }
    heads[i].y = std::clamp(heads[i].y, top, bottom);
    if (i > 0 && !on_level) heads[i].y = std::max(heads[i].y, heads[i - 1].y + 1.1f * f);
  }
  if (!heads.empty()) heads.back().y = std::min(heads.back().y, bottom);  // and back up from the bottom
  for (std::size_t i = heads.size(); i-- > 1;) heads[i - 1].y = std::min(heads[i - 1].y, heads[i].y - 1.1f * f);
  // Past the box's right edge, at the head's height, from the first frame: a
  // column of names that never moves sideways (one that starts inside and
  // jumps out near the end reads as leaving the plot), never across the
  // curves or the flips' marks inside the box.
  const float right = m.pixel(m.at(in.t1, in.lo)).x;
  for (const Head& h : heads) {
    const Series& s = in.series[h.series];
    const float x = right + 0.4f * f;
    view.texts.push_back({s.name, {x, h.y}, f, s.color, "series_label"});
  }
}

// Each reference level labelled on the value axis, as a tick is (inside the
// chart, a name would lie across the curves, the flips' marks and the playhead).
void add_level_labels(View& view, const StripChartInput& in, const ChartMap& m, float f) {
  for (const StripChartInput::Level& l : in.levels) {
    if (l.label.empty() || l.value < in.lo || l.value > in.hi) continue;
    view.texts.push_back({l.label, {4.0f, m.pixel(m.at(in.t0, l.value)).y - 0.5f * f}, f, kLevelColor, "level_label"});
  }
}

// Each point reached: a ring round it in its colour, its label to the right, just under its height.
void add_points(View& view, const StripChartInput& in, const ChartMap& m, float f) {
  for (const StripChartInput::Point& p : in.points) {
    if (p.t > in.playhead + 1e-9 || p.value < in.lo || p.value > in.hi) continue;
    const glm::dvec3 c = m.at(p.t, p.value);
    const double rw = 0.45 * f * (m.at(in.t0, in.hi).y - m.at(in.t0, in.lo).y) /
                      std::max(1.0f, m.pixel(m.at(in.t0, in.lo)).y - m.pixel(m.at(in.t0, in.hi)).y);
    std::vector<glm::dvec3> ring;
    for (int i = 0; i <= 32; ++i) {
      const double a = 2 * 3.14159265358979 * i / 32;
      ring.push_back({c.x + rw * std::cos(a), c.y + rw * std::sin(a), 0.0});
    }
    view.polylines.push_back({std::move(ring), p.color, 3.0f, false, "point"});
    // The label until the playhead reaches it (the stop at the point reads it); then the ring alone,
    // so that the playhead and the flips' marks never run across the words.
    const glm::vec2 px = m.pixel(c);
    if (m.pixel(m.at(in.playhead, in.lo)).x < px.x + 0.5f * f)
      view.texts.push_back({p.label, {px.x + 0.6f * f, px.y + 0.25f * f}, kNoteScale * f, p.color, "point_label"});
  }
}

// The time axis: numbers centred under their ticks, the unit once, after the
// last ("0 … 16 s"), whole steps between where they clear the ends.
void add_time_ticks(View& view, const StripChartInput& in, const ChartMap& m, float w, float f) {
  const Color ink = color_of(Meaning::ink);
  const glm::vec2 bottom_left = m.pixel(m.at(in.t0, in.lo)), bottom_right = m.pixel(m.at(in.t1, in.lo));
  const float y = bottom_left.y + 0.3f * f;
  const std::string t0 = format_number(in.t0, 3), t1 = format_number(in.t1, 3) + " s";
  const float x1 = std::min(centred_x(format_number(in.t1, 3), f, bottom_right.x), w - 0.2f * f - text_width(t1, f));
  view.texts.push_back({t0, {bottom_left.x, y}, f, ink, "tick"});
  view.texts.push_back({t1, {x1, y}, f, ink, "tick"});
  const double step = time_step(in.t1 - in.t0);
  // The ends keep the gap the steps keep between them (a wider one dropped 14 before "16 s").
  const float left_end = bottom_left.x + text_width(t0, f) + 0.3f * f, right_end = x1 - 0.3f * f;
  for (double t = std::ceil(in.t0 / step + 1e-9) * step; t < in.t1 - 1e-9; t += step) {
    const std::string label = format_number(t, 3);
    const float x = m.pixel(m.at(t, in.lo)).x, half = 0.5f * text_width(label, f);
    if (x - half > left_end && x + half < right_end) view.texts.push_back({label, {centred_x(label, f, x), y}, f, ink, "tick"});
  }
}

// Ticks (value range on the left, time range below), the series' key.
void add_chart_text(View& view, const StripChartInput& in, const ChartMap& m, const Head& head, float w, float f) {
  const Color ink = color_of(Meaning::ink);
  auto text = [&](const std::string& s, glm::vec2 p, Color c) {
    view.texts.push_back({s, p, f, c, "tick"});
  };
  auto value_text = [&](const std::string& s, glm::vec2 p, Color c) {  // where no level's name is
    if (clear_of_levels(in, m, p.y, f)) text(s, p, c);
  };
  const glm::vec2 top_left = m.pixel(m.at(in.t0, in.hi)), bottom_left = m.pixel(m.at(in.t0, in.lo));
  if (in.log10) {
    add_decade_ticks(view, in, m, f);
  } else {
    auto number = [&](double v) { return in.percent ? percent_text(v) : format_number(v, 3); };
    value_text(number(in.hi), {4.0f, top_left.y - 0.5f * f}, ink);
    value_text(number(in.lo), {4.0f, bottom_left.y - 0.5f * f}, ink);
  }
  if (!in.log10 && in.lo < 0 && in.hi > 0) {
    const float y0 = m.pixel(m.at(in.t0, 0)).y - 0.5f * f;
    // Only where it clears the range's ends.
    if (y0 > top_left.y + 0.5f * f && y0 + f < bottom_left.y - 0.5f * f) value_text("0", {4.0f, y0}, ink);
  }
  add_time_ticks(view, in, m, w, f);
  float x = w - head.key_w;
  add_level_labels(view, in, m, f);
  for (TextItem& n : level_notes(in, m, f)) view.texts.push_back(std::move(n));
  add_points(view, in, m, f);
  if (in.direct_labels) add_head_labels(view, in, m, f);
  for (const Series& s : in.direct_labels ? std::vector<Series>{} : in.series) {
    TextItem k{s.name, {x, head.key_y}, head.key_px, s.color, "key"};
    k.key = true;
    view.texts.push_back(std::move(k));
    x += text_width(s.name, head.key_px) + 1.2f * head.key_px;
  }
  for (const std::string& b : band_names(in)) {
    TextItem k{b, {x, head.key_y}, head.key_px, {0.35f, 0.55f, 0.95f, 0.9f}, "key"};
    k.key = true;
    view.texts.push_back(std::move(k));
    x += text_width(b, head.key_px) + 1.2f * head.key_px;
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
  add_chart_lines(view, in, m, font_px);
  add_chart_text(view, in, m, head, static_cast<float>(width_px), font_px);
}

}  // namespace tumble::viz
