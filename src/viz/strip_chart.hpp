// A strip chart: chosen series over time, drawn so far, with a playhead.
// Orthographic camera over the plane z = 0; the chart maps [t0, t1] × [lo, hi]
// into the view, so lines and the labels (pixels) line up exactly.
#pragma once

#include <string>
#include <vector>

#include "viz/draw_list.hpp"

namespace tumble::viz {

/// Tint of the slowed stretches (translucent, lit face-on).
inline constexpr Color kSlowBandColor{0.35f, 0.55f, 0.95f, 0.22f};
/// Reference levels' dashes and names: dark grey, no series' colour.
inline constexpr Color kLevelColor{0.25f, 0.27f, 0.32f, 0.85f};

struct Series {
  std::string name;            ///< as shown in the key, e.g. "ω₁"
  std::vector<double> values;  ///< one per sample of StripChartInput::times
  Color color;
};

struct StripChartInput {
  std::vector<double> times;   ///< s, ascending; samples up to the playhead
  std::vector<Series> series;
  double t0 = 0, t1 = 1;       ///< s, the time axis
  double lo = -1, hi = 1;      ///< value axis (the caller's unit)
  double playhead = 0;         ///< s
  /// Stretches (s) played at another speed: shaded over the plot's height, `label` ("×1/8") on top.
  struct Band {
    double start, end;
    std::string label;
  };
  std::vector<Band> shaded;
  int frame_h = 0;             ///< frame height for the text roles' sizes (0: every text at font_px)
  double text_scale = 1;       ///< the scene's text scale ([draw] text_scale), with frame_h
  /// Times (s) marked by a thin vertical line once the playhead has passed them (a lesson's flips).
  std::vector<double> marks;
  /// Values are log10 of the quantity: the value axis is ticked at its decades (10⁻⁸, 10⁻⁴, …).
  bool log10 = false;
  /// Each series named at its curve's head, in its colour (no key row): a few curves told apart at a glance.
  bool direct_labels = false;
  /// Reference values (the value axis' unit) drawn as dashed lines across the chart, each labelled on the
  /// value axis, as a tick is (the view's title says what each is).
  struct Level {
    double value;
    std::string label;
    std::string note = {};  ///< what the level is ("separatrix, 3×10⁻⁶"), written along its line inside the chart
  };
  std::vector<Level> levels;
  /// Points marked by a ring in `color` with `label` beside it, once the playhead reaches `t`
  /// (value in the value axis' unit): an event on a curve, e.g. where it crosses a level.
  struct Point {
    double t, value;
    std::string label;
    Color color;
  };
  std::vector<Point> points;
  /// A linear value axis of fractions ticked in per cent ("+120 %", "0", "−10 %"): a relative error read as such.
  bool percent = false;
};

/// Fills `view` (camera included) for a viewport of `width_px` × `height_px`:
/// the series' key (name in its colour) top-right; ticks at `font_px`.
void build_strip_chart(View& view, const StripChartInput& in, int width_px, int height_px, float font_px);

/// A fraction in per cent, signed and whole: "+86 %", "0" (under half a per cent), "−10 %".
std::string percent_text(double fraction);

/// Maps chart coordinates (t, value) to the world plane the chart is drawn in.
class ChartMap {
 public:
  ChartMap(const StripChartInput& in, int width_px, int height_px, float font_px);
  glm::dvec3 at(double t, double v) const;
  glm::vec2 pixel(const glm::dvec3& world) const;  ///< top-left origin, px
  double value_at(float pixel_y) const;            ///< the value axis' value at a pixel row
  double aspect() const { return aspect_; }

 private:
  double t0_, t1_, lo_, hi_, aspect_;
  double x0_, x1_, y0_, y1_;  // plot rectangle in world units (y up, half height 1)
  int w_, h_;
};

}  // namespace tumble::viz
