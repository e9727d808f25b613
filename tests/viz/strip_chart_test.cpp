// The strip chart: its map, levels, bands, axes and the curves' names.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "viz/captions.hpp"
#include "viz/strip_chart.hpp"
#include "viz/text_layout.hpp"

namespace tumble::viz {
namespace {

TEST(StripChart, SeriesAndPlayheadLandOnTheChartMap) {
  StripChartInput in;
  in.times = {0, 1, 2};
  in.series = {{"wbx", {0.0, 1.0, -1.0}, {1, 0, 0, 1}}};
  in.t0 = 0, in.t1 = 4, in.lo = -2, in.hi = 2, in.playhead = 2;
  View v;
  build_strip_chart(v, in, 400, 200, 12.0f);
  const ChartMap m(in, 400, 200, 12.0f);
  bool series = false, playhead = false;
  for (const PolylineItem& p : v.polylines) {
    EXPECT_FALSE(p.fade);
    if (p.points.size() == 3) series = p.points[1] == m.at(1, 1.0) && p.points[2] == m.at(2, -1.0);
    if (p.points.size() == 2 && p.points[0] == m.at(2, -2) && p.points[1] == m.at(2, 2)) playhead = true;
  }
  EXPECT_TRUE(series);
  EXPECT_TRUE(playhead);
  // The chart's corners project (orthographic camera) to the pixels the labels use.
  glm::vec2 px;
  ASSERT_TRUE(project_to_viewport(v.camera, 400, 200, m.at(0, 2), px));
  EXPECT_NEAR(px.x, m.pixel(m.at(0, 2)).x, 1e-3);
  EXPECT_NEAR(px.y, m.pixel(m.at(0, 2)).y, 1e-3);
  EXPECT_GT(px.x, 0);
  EXPECT_LT(px.x, 400);
}

TEST(StripChart, ReferenceLevelsAreDashedLinesNamedOnTheValueAxis) {
  StripChartInput in;
  in.times = {0, 1};
  in.series = {{"e", {0.0, 0.1}, {1, 0, 0, 1}}};
  in.t0 = 0, in.t1 = 4, in.lo = -0.2, in.hi = 1, in.playhead = 1;
  in.levels = {{0.97, "L\u00b2/2I\u2081"}, {-0.33, "below the axis"}};
  View v;
  build_strip_chart(v, in, 600, 300, 12.0f);
  const ChartMap m(in, 600, 300, 12.0f);
  int dashes = 0;
  for (const PolylineItem& p : v.polylines)
    if (p.color == kLevelColor) {
      ++dashes;
      ASSERT_EQ(p.points.size(), 2u);
      EXPECT_NEAR(p.points[0].y, m.at(0, 0.97).y, 1e-9) << "on the level's value";
      EXPECT_NEAR(p.points[1].y, p.points[0].y, 1e-12) << "level";
    }
  EXPECT_EQ(dashes, 40) << "one dashed line; the level outside [lo, hi] is left out";
  int names = 0;
  bool top_tick = false;
  const float y = m.pixel(m.at(0, 0.97)).y;
  for (const TextItem& t : v.texts) {
    if (t.name == "level_label") {
      ++names;
      EXPECT_EQ(t.text, "L\u00b2/2I\u2081");
      EXPECT_NEAR(t.position_px.y + 0.5f * t.size_px, y, 1e-3) << "centred on its line";
      EXPECT_LT(t.position_px.x + text_width(t.text, t.size_px), m.pixel(m.at(0, 0.97)).x) << "left of the chart";
    }
    top_tick = top_tick || (t.name == "tick" && t.text == "1" && t.position_px.x == 4.0f);  // the value axis's, not time's 1 s
  }
  EXPECT_EQ(names, 1);
  EXPECT_FALSE(top_tick) << "the value tick 1, a line from the level's name, gives way to it";
}

TEST(StripChart, ALevelsNoteRunsAlongItsLineInsideTheBox) {
  StripChartInput in;
  in.times = {0, 1};
  in.series = {{"e", {-8.0, -7.0}, {1, 0, 0, 1}}};
  in.t0 = 0, in.t1 = 16, in.lo = -9, in.hi = 0, in.playhead = 1, in.log10 = true;
  in.levels = {{-0.07, "", "pure e\u2081 spin, +86 %"}, {-5.5, "", "separatrix, 3\u00d710\u207b\u2076"}};
  View v;
  build_strip_chart(v, in, 900, 500, 20.0f);
  const ChartMap m(in, 900, 500, 20.0f);
  const glm::vec2 lo = m.pixel(m.at(in.t0, in.lo)), hi = m.pixel(m.at(in.t1, in.hi));
  int notes = 0;
  for (const TextItem& t : v.texts) {
    EXPECT_NE(t.name, "level_label") << "a level without an axis label has none";
    if (t.name != "level_note") continue;
    ++notes;
    const float x1 = t.position_px.x + text_width(t.text, t.size_px), line = m.pixel(m.at(0, t.text[0] == 'p' ? -0.07 : -5.5)).y;
    EXPECT_GT(t.position_px.x, lo.x) << t.text;
    EXPECT_LT(x1, hi.x) << t.text;
    EXPECT_GT(t.position_px.y, hi.y) << t.text << ": under the top border";
    EXPECT_LT(t.position_px.y + t.size_px, lo.y) << t.text << ": over the bottom border";
    // Beside its line, not across it: just above it, or (near the top border) just under it.
    const bool above = t.position_px.y + t.size_px <= line && t.position_px.y + 1.5f * t.size_px > line;
    const bool under = t.position_px.y >= line && t.position_px.y < line + 0.5f * t.size_px;
    EXPECT_TRUE(above || under) << t.text;
  }
  EXPECT_EQ(notes, 2);
}

// The playhead sweeps through a level's note and the flips' marks stand under
// it: each line is broken round the words (a line through a word strikes it
// out) and whole elsewhere, at every playhead position.
TEST(StripChart, ThePlayheadAndTheMarksLeaveTheLevelsNotesUnstruck) {
  StripChartInput in;
  in.times = {0, 1};
  in.series = {{"e", {-8.0, -7.0}, {1, 0, 0, 1}}};
  in.t0 = 0, in.t1 = 16, in.lo = -9, in.hi = 0, in.log10 = true;
  in.levels = {{-1.0, "", "pure e\u2081 spin, +86 %"}, {-5.5, "", "separatrix, 3\u00d710\u207b\u2076"}};
  in.marks = {1.8, 5.1, 8.4, 11.7, 14.9};  // none at a playhead's step (two lines at one x)
  const ChartMap m(in, 900, 500, 20.0f);
  int broken = 0;
  for (double playhead = 0; playhead <= 16; playhead += 0.25) {
    in.playhead = playhead;
    View v;
    build_strip_chart(v, in, 900, 500, 20.0f);
    std::vector<Box> notes;
    for (const TextItem& t : v.texts)
      if (t.name == "level_note") notes.push_back(text_box(t));
    ASSERT_EQ(notes.size(), 2u);
    std::map<double, double> drawn;  // each vertical line's x (world) and its length drawn, in value units
    for (const PolylineItem& p : v.polylines) {
      if (p.name != "mark" && p.name != "playhead") continue;
      ASSERT_EQ(p.points.size(), 2u);
      const glm::vec2 a = m.pixel(p.points[0]), b = m.pixel(p.points[1]);
      for (const Box& n : notes)
        EXPECT_FALSE(a.x + 1 > n.x0 && a.x - 1 < n.x1 && std::max(a.y, b.y) + 1 > n.y0 && std::min(a.y, b.y) - 1 < n.y1)
            << p.name << " at x " << a.x << ", playhead " << playhead << ": through a note";
      drawn[p.points[0].x] += std::abs(p.points[1].y - p.points[0].y);
    }
    const double full = m.at(0, in.hi).y - m.at(0, in.lo).y;
    EXPECT_EQ(drawn.size(), 1 + std::count_if(in.marks.begin(), in.marks.end(), [&](double t) { return t <= playhead; }));
    for (const auto& [x, length] : drawn) {
      EXPECT_GT(length, 0.75 * full) << "a line broken only round a note";
      broken += length < full - 1e-9;
    }
  }
  EXPECT_GT(broken, 10) << "lines that did cross a note's place";
}

TEST(StripChart, APointIsRingedOnlyOnceThePlayheadReachesIt) {
  StripChartInput in;
  in.times = {0, 1, 2};
  in.series = {{"e", {-8.0, -6.0, -3.0}, {1, 0, 0, 1}}};
  in.t0 = 0, in.t1 = 16, in.lo = -9, in.hi = 0, in.log10 = true;
  in.points = {{1.5, -5.5, "Euler crosses it, 1.5 s", {0.8f, 0.1f, 0.2f, 1}}};
  auto drawn = [&](double playhead) {
    in.playhead = playhead;
    View v;
    build_strip_chart(v, in, 900, 500, 20.0f);
    const ChartMap m(in, 900, 500, 20.0f);
    int rings = 0, labels = 0;
    for (const PolylineItem& p : v.polylines)
      if (p.name == "point") {
        ++rings;
        double mean_x = 0, mean_y = 0;
        for (std::size_t i = 0; i + 1 < p.points.size(); ++i) mean_x += p.points[i].x, mean_y += p.points[i].y;
        mean_x /= double(p.points.size() - 1), mean_y /= double(p.points.size() - 1);
        EXPECT_NEAR(mean_x, m.at(1.5, -5.5).x, 1e-9) << "round the point";
        EXPECT_NEAR(mean_y, m.at(1.5, -5.5).y, 1e-9) << "round the point";
      }
    for (const TextItem& t : v.texts) labels += t.name == "point_label" && t.text == "Euler crosses it, 1.5 s";
    return rings * 10 + labels;
  };
  EXPECT_EQ(drawn(1.4), 0) << "not before the playhead reaches it";
  EXPECT_EQ(drawn(1.5), 11) << "ring and label";
  EXPECT_EQ(drawn(8.0), 10) << "the ring stays; the label goes before the playhead runs across it";
}

TEST(StripChart, SlowedStretchesAreShadedBandsWithTheirSpeed) {
  StripChartInput in;
  in.t0 = 0, in.t1 = 6, in.lo = -1, in.hi = 1;
  in.shaded = {{1.5, 2.5, "×1/8"}};
  View v;
  build_strip_chart(v, in, 800, 200, 14.0f);
  ASSERT_EQ(v.surfaces.size(), 1u);
  const ChartMap m(in, 800, 200, 14.0f);
  const glm::dvec3 centre(v.surfaces[0].model[3]), half_t(v.surfaces[0].model[0]);
  EXPECT_NEAR(centre.x - half_t.x, m.at(1.5, 0).x, 1e-12);
  EXPECT_NEAR(centre.x + half_t.x, m.at(2.5, 0).x, 1e-12);
  EXPECT_LT(v.surfaces[0].color.a, 0.5f);
  // Named in the chart's key (under the axis a name would read as a time tick).
  bool label = false;
  for (const TextItem& t : v.texts) label = label || (t.key && t.text.find("×1/8 slow motion") != std::string::npos);
  EXPECT_TRUE(label);
}

}  // namespace
}  // namespace tumble::viz

namespace tumble::viz {
namespace {

TEST(StripChart, ALogAxisIsTickedAtItsDecades) {
  StripChartInput in;
  in.times = {0, 1, 2};
  in.series = {{"euler", {-3.0, -2.0, -1.0}, {1, 0, 0, 1}}};
  in.t0 = 0, in.t1 = 4, in.lo = -10, in.hi = 1, in.playhead = 2;
  in.log10 = true;
  View v;
  build_strip_chart(v, in, 600, 200, 12.0f);
  const ChartMap m(in, 600, 200, 12.0f);
  std::vector<std::string> ticks;
  for (const TextItem& t : v.texts)
    if (t.name == "tick" && t.position_px.x < 10) {
      ticks.push_back(t.text);
      if (t.text == "10\u207b\u2074") { EXPECT_NEAR(t.position_px.y + 6.0f, m.pixel(m.at(0, -4)).y, 1e-3); }
    }
  // Eleven decades, every second named: 10⁻¹⁰ … 10⁰, no linear end values.
  EXPECT_EQ(ticks, (std::vector<std::string>{"10\u207b\u00b9\u2070", "10\u207b\u2078", "10\u207b\u2076", "10\u207b\u2074",
                                             "10\u207b\u00b2", "10\u2070"}));
}

TEST(StripChart, ALogAxisNamesTenToTheZeroWhereItHoldsIt) {
  StripChartInput in;
  in.times = {0, 1};
  in.series = {{"euler", {-3.0, -1.0}, {1, 0, 0, 1}}};
  in.t0 = 0, in.t1 = 2, in.lo = -9, in.hi = 1, in.playhead = 1;  // ten decades, a decade above 10⁰
  in.log10 = true;
  View v;
  build_strip_chart(v, in, 600, 200, 12.0f);
  std::vector<std::string> ticks;
  for (const TextItem& t : v.texts)
    if (t.name == "tick" && t.position_px.x < 10) ticks.push_back(t.text);
  // Every second decade counted from 10⁰, not from the floor (10⁻⁹, 10⁻⁷, … would skip 10⁰).
  EXPECT_EQ(ticks, (std::vector<std::string>{"10\u207b\u2078", "10\u207b\u2076", "10\u207b\u2074", "10\u207b\u00b2",
                                             "10\u2070"}));
}

TEST(StripChart, DirectLabelsNameEachCurveAtItsHeadApart) {
  StripChartInput in;
  in.times = {0, 1, 2};
  // Two heads a hair apart and one far below; the third stopped a sample early.
  in.series = {{"euler", {-1.0, -0.5, 0.0}, {1, 0, 0, 1}},
               {"rk4", {-1.0, -0.5, -0.01}, {0, 1, 0, 1}},
               {"splitting", {-8.0, -9.0, std::nan("")}, {0, 0, 1, 1}}};
  in.t0 = 0, in.t1 = 4, in.lo = -10, in.hi = 1, in.playhead = 2;  // room to the right of the playhead
  in.direct_labels = true;
  View v;
  build_strip_chart(v, in, 600, 200, 12.0f);
  const ChartMap m(in, 600, 200, 12.0f);
  std::vector<const TextItem*> labels;
  for (const TextItem& t : v.texts) {
    EXPECT_NE(t.name, "key") << "no key row: the curves are named where they are";
    if (t.name == "series_label") labels.push_back(&t);
  }
  ASSERT_EQ(labels.size(), 3u);
  for (const TextItem* t : labels) {
    const std::size_t i = t->text == "euler" ? 0 : t->text == "rk4" ? 1 : 2;
    EXPECT_EQ(t->color, in.series[i].color) << t->text;
    const glm::vec2 head = m.pixel(m.at(i == 2 ? 1 : 2, in.series[i].values[i == 2 ? 1 : 2]));
    EXPECT_GT(t->position_px.x, head.x) << t->text;                                   // just right of its head
    EXPECT_LT(t->position_px.x + text_width(t->text, 12.0f), 600.0f) << t->text;      // inside the view
    EXPECT_NEAR(t->position_px.y + 6.0f, head.y, i == 2 ? 1e-3 : 13.2) << t->text;   // at its height, or pushed apart
  }
  EXPECT_GE(std::abs(labels[0]->position_px.y - labels[1]->position_px.y), 1.1f * 12.0f - 1e-3f);
}

TEST(StripChart, DirectLabelsStayOffThePlayheadAndBordersAtTheEnd) {
  StripChartInput in;
  in.times = {0, 1, 2};
  // The run's end: no room right of the heads. The top curve lies on the chart's upper edge.
  in.series = {{"explicit Euler", {-1.0, 0.0, 1.0}, {1, 0, 0, 1}}, {"rk4", {-8.0, -8.0, -8.0}, {0, 1, 0, 1}}};
  in.t0 = 0, in.t1 = 2, in.lo = -10, in.hi = 1, in.playhead = 2;
  in.direct_labels = true;
  View v;
  build_strip_chart(v, in, 600, 200, 12.0f);
  const ChartMap m(in, 600, 200, 12.0f);
  const glm::vec2 top_left = m.pixel(m.at(0, in.hi)), bottom_right = m.pixel(m.at(2, in.lo));
  int named = 0;
  for (const TextItem& t : v.texts) {
    if (t.name != "series_label") continue;
    ++named;
    const float x0 = t.position_px.x, x1 = x0 + text_width(t.text, 12.0f);
    EXPECT_GE(x0, bottom_right.x + 0.4f * 12.0f) << t.text;  // clear of the playhead (at the box's right end)
    EXPECT_LE(x1, 600.0f - 0.2f * 12.0f) << t.text;          // not clipped at the view's right edge
    EXPECT_GT(t.position_px.y, top_left.y) << t.text;        // under the top border, not on it
    EXPECT_LT(t.position_px.y + 12.0f, bottom_right.y) << t.text;
  }
  EXPECT_EQ(named, 2);
}

TEST(StripChart, DirectLabelsNearTheEndSitPastTheRightBorderNotAcrossIt) {
  StripChartInput in;
  in.times = {0, 1, 2, 3, 3.5};
  in.series = {{"explicit Euler", {0.1, 0.2, 0.3, 0.4, 0.45}, {1, 0, 0, 1}}};
  in.t0 = 0, in.t1 = 4, in.lo = 0, in.hi = 1, in.playhead = 3.5;  // the head less than a name's width from the right border
  in.direct_labels = true;
  View v;
  build_strip_chart(v, in, 600, 200, 12.0f);
  const ChartMap m(in, 600, 200, 12.0f);
  const float right = m.pixel(m.at(4, 0)).x;
  int named = 0;
  for (const TextItem& t : v.texts) {
    if (t.name != "series_label") continue;
    ++named;
    const float x0 = t.position_px.x, x1 = x0 + text_width(t.text, 12.0f);
    EXPECT_TRUE(x1 < right || x0 > right) << "\"" << t.text << "\" spans " << x0 << "-" << x1 << " across the border at " << right;
  }
  EXPECT_EQ(named, 1);
}

// Early and late, a curve's name stands in the same column past the box's
// right edge: it never jumps out of the plot as the head nears the edge.
TEST(StripChart, DirectLabelsStandInOneColumnPastTheBox) {
  std::vector<float> xs;
  for (std::size_t n : {2u, 5u}) {
    StripChartInput in;
    in.times = {0, 1, 2, 3, 3.5};
    in.series = {{"explicit Euler", {0.1, 0.2, 0.3, 0.4, 0.45}, {1, 0, 0, 1}}};
    in.times.resize(n), in.series[0].values.resize(n);
    in.t0 = 0, in.t1 = 4, in.lo = 0, in.hi = 1, in.playhead = in.times.back();
    in.direct_labels = true;
    View v;
    build_strip_chart(v, in, 600, 200, 12.0f);
    const float right = ChartMap(in, 600, 200, 12.0f).pixel(ChartMap(in, 600, 200, 12.0f).at(4, 0)).x;
    for (const TextItem& t : v.texts)
      if (t.name == "series_label") {
        xs.push_back(t.position_px.x);
        EXPECT_GT(t.position_px.x, right) << "past the box, not over its curves and marks (playhead " << in.playhead << ")";
      }
  }
  ASSERT_EQ(xs.size(), 2u);
  EXPECT_EQ(xs[0], xs[1]);
}

TEST(StripChart, DirectLabelsKeepTheirOrderWhenACurveDipsForAMoment) {
  StripChartInput in;
  in.times = {0, 1, 2, 3};
  // "splitting" lies above "rk4" but dips far under it at its head (a zero crossing of a signed error).
  in.series = {{"rk4", {-9.0, -8.5, -8.2, -8.0}, {0, 1, 0, 1}}, {"splitting", {-6.0, -4.0, -5.0, -10.0}, {0, 0, 1, 1}}};
  in.t0 = 0, in.t1 = 3, in.lo = -12, in.hi = 1, in.playhead = 3;
  in.direct_labels = true;
  View v;
  build_strip_chart(v, in, 600, 300, 12.0f);
  float rk4_y = 0, splitting_y = 0;
  for (const TextItem& t : v.texts)
    if (t.name == "series_label") (t.text == "rk4" ? rk4_y : splitting_y) = t.position_px.y;
  EXPECT_LT(splitting_y + 1.1f * 12.0f - 1e-3f, rk4_y + 1e-3f) << "the higher curve's name stays above";
}

// A relative error on a linear axis reads in per cent: its ends, and a level's label.
TEST(StripChart, APercentAxisReadsTheFractionInPerCent) {
  EXPECT_EQ(percent_text(0.862), "+86 %");
  EXPECT_EQ(percent_text(3e-6), "0");
  EXPECT_EQ(percent_text(-0.3), "\u221230 %");
  StripChartInput in;
  in.times = {0, 1};
  in.series = {{"e", {0.0, 0.1}, {1, 0, 0, 1}}};
  in.t0 = 0, in.t1 = 16, in.lo = -0.3, in.hi = 1.2, in.playhead = 1, in.percent = true;
  View v;
  build_strip_chart(v, in, 640, 380, 22.0f);
  std::vector<std::string> values;
  for (const TextItem& t : v.texts)
    if (t.name == "tick" && t.position_px.x == 4.0f) values.push_back(t.text);
  EXPECT_NE(std::find(values.begin(), values.end(), "+120 %"), values.end());
  EXPECT_NE(std::find(values.begin(), values.end(), "\u221230 %"), values.end());
  EXPECT_EQ(std::find(values.begin(), values.end(), "1.2"), values.end()) << "no bare fraction";
}

// A curve lying on a level (RK4's error on the separatrix's) has its name
// just above the dashed line, not struck through by it; the names above make way.
TEST(StripChart, ACurveNameStaysOffALevelsLine) {
  StripChartInput in;
  in.times = {0, 1, 2, 3, 4};
  in.series = {{"Euler", {0.0, 0.02, 0.05, 0.08, 0.1}, {1, 0, 0, 1}}, {"RK4", {0, 0, 0, 0, 0}, {0.8f, 0.6f, 0, 1}}};
  in.t0 = 0, in.t1 = 16, in.lo = -0.3, in.hi = 1.2, in.playhead = 4, in.direct_labels = true;
  in.levels = {{0.0, "0"}};
  const float f = 22.0f;
  View v;
  build_strip_chart(v, in, 640, 380, f);
  const ChartMap m(in, 640, 380, f);
  const float line = m.pixel(m.at(0, 0.0)).y;
  std::vector<const TextItem*> names;
  for (const TextItem& t : v.texts)
    if (t.name == "series_label") names.push_back(&t);
  ASSERT_EQ(names.size(), 2u);
  for (const TextItem* t : names)
    EXPECT_TRUE(t->position_px.y + f < line || t->position_px.y > line) << t->text << " lies across the level's line";
  EXPECT_GE(std::abs(names[0]->position_px.y - names[1]->position_px.y), f) << "the names keep apart";
}

// The time axis: every whole step numbered (none crowded out by a unit at
// the start), the unit once, after the last number.
TEST(StripChart, TheTimeAxisNumbersEveryStepAndNamesItsUnitOnce) {
  StripChartInput in;
  in.times = {0, 1};
  in.series = {{"e", {0.0, 0.1}, {1, 0, 0, 1}}};
  in.t0 = 0, in.t1 = 16, in.lo = -0.3, in.hi = 1.2, in.playhead = 1;
  View v;
  build_strip_chart(v, in, 500, 300, 22.0f);
  std::vector<std::string> times;
  for (const TextItem& t : v.texts)
    if (t.name == "tick" && t.position_px.x != 4.0f) times.push_back(t.text);
  for (const char* want : {"0", "2", "4", "6", "8", "10", "12", "14", "16 s"})
    EXPECT_NE(std::find(times.begin(), times.end(), want), times.end()) << want;
  EXPECT_EQ(std::count_if(times.begin(), times.end(), [](const std::string& t) { return t.find(" s") != std::string::npos; }), 1);
}

}  // namespace
}  // namespace tumble::viz
