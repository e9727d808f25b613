// How the layout serves a lesson's figure: declared viewports fill the views'
// area (no empty band where captions once went), keys that views would repeat
// become one frame key in rows of its own strip, world cameras come close
// enough for the whole video's bodies to fill their content, and the cells of
// a comparison grid share one camera. GL-free: plans and draw lists.
#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "compose/camera_fit.hpp"
#include "compose/frame_builder.hpp"
#include "compose/frame_layout.hpp"
#include "compose/view_layout.hpp"
#include "compose/views/kinds.hpp"
#include "compose/world_views.hpp"
#include "scene/frame_runs.hpp"
#include "scene/scene.hpp"
#include "viz/captions.hpp"
#include "viz/key.hpp"
#include "viz/palette.hpp"
#include "viz/text_layout.hpp"

namespace {

using namespace tumble;
using compose::FrameNeeds;
using compose::FramePlan;
using compose::ViewNeeds;

std::vector<viz::KeyEntry> sphere_like_key() {
  return {viz::key_entry(viz::Meaning::momentum_point, "\u03a0: L in body axes"),
          viz::key_entry(viz::Meaning::polhode, "polhode"), viz::key_entry(viz::Meaning::separatrix, "separatrix")};
}

ViewNeeds view(std::array<double, 4> viewport, std::vector<viz::KeyEntry> key = {}) {
  ViewNeeds v;
  v.viewport = viewport;
  v.kind = "momentum_sphere";
  v.title = "a view";
  v.key = std::move(key);
  return v;
}

FrameNeeds needs(std::vector<ViewNeeds> views) {
  FrameNeeds n;
  n.width = 960, n.height = 540;
  n.views = std::move(views);
  n.captions = {"a caption at the foot of the frame"};
  return n;
}

TEST(LayoutFill, DeclaredViewportsFillTheViewsArea) {
  // As dzhanibekov_explained declares them: 0.6 + 0.3 of the height, 0.1 once kept for captions.
  const FramePlan p = compose::plan_frame(
      needs({view({0, 0, 0.5, 0.6}), view({0.5, 0, 0.5, 0.6}), view({0, 0.6, 1, 0.3})}));
  ASSERT_GT(p.captions.y1, p.captions.y0);
  const compose::ViewPlan& plot = p.views[2];
  EXPECT_NEAR(plot.y + plot.height, p.captions.y0, 1.0) << "the lowest view reaches the caption strip";
  EXPECT_EQ(p.views[0].y, 0);
  // Proportions kept: the top row is twice the bottom one.
  EXPECT_NEAR(double(p.views[0].height) / plot.height, 2.0, 0.02);
  EXPECT_NEAR(p.views[0].y + p.views[0].height, plot.y, 1);
}

TEST(LayoutFill, RepeatedKeysBecomeOneFrameKeyInItsOwnStrip) {
  const std::vector<viz::KeyEntry> world = {viz::key_entry(viz::Meaning::L, "L, fixed in space")};
  const FramePlan p = compose::plan_frame(needs({view({0, 0, 1, 0.5}, world), view({0, 0.5, 0.33, 0.5}, sphere_like_key()),
                                                 view({0.33, 0.5, 0.34, 0.5}, sphere_like_key()),
                                                 view({0.67, 0.5, 0.33, 0.5}, sphere_like_key())}));
  for (const compose::ViewPlan& v : p.views) {
    EXPECT_TRUE(v.key.empty());
    EXPECT_FALSE(v.key_at);
    EXPECT_FLOAT_EQ(v.content.x1, float(v.width) - 0.5f * viz::text_px(viz::TextRole::key, 540, 1)) << "no key strip";
  }
  ASSERT_EQ(p.frame_key.size(), 4u);  // every entry once: L and the spheres' three
  EXPECT_EQ(p.frame_key[0].text, "L, fixed in space");
  // Its strip lies between the views and the captions.
  EXPECT_GT(p.frame_key_box.y1, p.frame_key_box.y0);
  EXPECT_LE(p.frame_key_box.y1, p.captions.y0);
  for (const compose::ViewPlan& v : p.views) EXPECT_LE(float(v.y + v.height), p.frame_key_box.y0 + 1);
  // Drawn in rows inside it, each entry's text once.
  viz::DrawList dl;
  const float px = p.frame_key_px;
  const viz::Box b = viz::add_key_row(dl.texts, p.frame_key, 480, p.frame_key_box.y0 + 0.5f * px, px, 960 - px);
  EXPECT_GE(b.y0, p.frame_key_box.y0);
  EXPECT_LE(b.y1, p.frame_key_box.y1);
  for (const viz::TextItem& t : dl.texts) {
    const viz::Box tb = viz::text_box(t);
    EXPECT_GE(tb.x0, b.x0);
    EXPECT_LE(tb.x1, b.x1 + 0.5f);
    for (const viz::TextItem& u : dl.texts) {
      if (&u != &t) {
        EXPECT_FALSE(tb.overlaps(viz::text_box(u))) << t.text << " / " << u.text;
      }
    }
  }
}

TEST(LayoutFill, KeysOfTheirOwnStayBesideTheirViews) {
  // dzhanibekov_explained's: the world's and the sphere's keys share only the axes' entry.
  const viz::KeyEntry axes{viz::Swatch::line, {viz::kAxisColors[0], viz::kAxisColors[1], viz::kAxisColors[2]}, "e1 e2 e3"};
  std::vector<viz::KeyEntry> world = {axes, viz::key_entry(viz::Meaning::L, "L")}, sphere = sphere_like_key();
  sphere.insert(sphere.begin(), axes);
  // Keys' text is ~3 % of the frame height: a frame twice as wide as 960x540
  // leaves each half-width view room for its key beside the content.
  FrameNeeds wide = needs({view({0, 0, 0.5, 0.6}, world), view({0.5, 0, 0.5, 0.6}, sphere)});
  wide.width = 1920;
  const FramePlan p = compose::plan_frame(wide);
  EXPECT_TRUE(p.frame_key.empty());
  EXPECT_EQ(p.views[0].key.size(), 2u);
  EXPECT_EQ(p.views[1].key.size(), 4u);
  EXPECT_TRUE(p.views[0].key_at && p.views[1].key_at);
  // At 960x540 the sphere's key beside its 480 px view would leave the content
  // under 62 % of its width: it goes to the frame key, every entry once.
  const FramePlan narrow = compose::plan_frame(needs({view({0, 0, 0.5, 0.6}, world), view({0.5, 0, 0.5, 0.6}, sphere)}));
  EXPECT_TRUE(narrow.views[1].key.empty());
  EXPECT_FALSE(narrow.frame_key.empty());
  for (const viz::KeyEntry& e : sphere)
    EXPECT_EQ(std::count_if(narrow.frame_key.begin(), narrow.frame_key.end(),
                            [&](const viz::KeyEntry& x) { return viz::same_entry(x, e); }),
              1)
        << e.text;
}

// The largest share of its content's half width or height the whole video's
// points reach in view `i` (1: the content's edge).
double fill(const scene::Scene& s, std::size_t i, int w, int h) {
  const double fps = s.render.output.fps;
  const long count = scene::frame_clock(s, fps).count();
  const auto runs = scene::simulate_runs(s, count, fps);
  const compose::FrameBuilder fb(s, runs, fps, w, h);
  double reach = 0;
  for (long k = 0; k < count; k += 3) {
    const viz::DrawList dl = fb.build(k);
    if (dl.views.size() <= i) continue;
    const viz::View& v = dl.views[i];
    const compose::PixelRect content =
        compose::content_rect(v, compose::view_rect(v, int(i), int(dl.views.size()), dl.columns, w, h));
    const compose::CameraMatrices m = compose::camera_matrices(v.camera, content.aspect());
    for (const glm::dvec3& p : compose::solid_points(v)) {
      const glm::vec4 c = m.proj * m.view * glm::vec4(glm::vec3(p), 1.0f);
      if (c.w > 0) reach = std::max({reach, double(std::abs(c.x / c.w)), double(std::abs(c.y / c.w))});
    }
  }
  return reach;
}

scene::Scene shipped(const char* name) {
  return scene::load_scene(std::filesystem::path(TUMBLE_SOURCE_DIR) / "scenes" / name);
}

TEST(LayoutFill, WorldViewsComeCloseEnoughForTheBodiesToFillTheirContent) {
  // The scene's camera was set for a whole frame; in its view the T-handle fills the content.
  EXPECT_GT(fill(shipped("dzhanibekov_explained.toml"), 0, 960, 540), 0.8);
  EXPECT_LE(fill(shipped("dzhanibekov_explained.toml"), 0, 960, 540), 1.0);
  // With name labels a label's line stays free above and below the bodies (here about a fifth of the half
  // height, and more since the clock line shortens the content at 960x540).
  EXPECT_GT(fill(shipped("tennis_racket.toml"), 0, 960, 540), 0.7);
  // A comparison grid's automatic camera, every cell. Its arrows' tips, the
  // extreme points, keep their names' room (1.4 label heights, 25 px, each
  // side: a fifth of a 268 px cell's half width at 960x540) inside the fill
  // margin (0.1), so the bodies reach at least 0.9 - 0.2.
  const scene::Scene mc = shipped("methods_compare.toml");
  double widest = 0;
  for (std::size_t i = 0; i < 2; ++i) widest = std::max(widest, fill(mc, i, 960, 540));  // one row above the plot
  EXPECT_GT(widest, 0.7);
  EXPECT_LE(widest, 1.0);
}

TEST(LayoutFill, ComparisonCellsShareOneCamera) {
  const scene::Scene s = shipped("methods_compare.toml");
  const double fps = s.render.output.fps;
  const long count = scene::frame_clock(s, fps).count();
  const auto runs = scene::simulate_runs(s, count, fps);
  ASSERT_GT(runs.size(), 1u);
  const compose::FrameBuilder fb(s, runs, fps, 320, 240);
  const viz::DrawList dl = fb.build(count / 2);
  for (const viz::View& v : dl.views) {
    if (v.name != "world") continue;  // the plot under the cells has a chart's camera
    EXPECT_EQ(v.camera.position, dl.views[0].camera.position);
    EXPECT_EQ(v.camera.target, dl.views[0].camera.target);
  }
}

TEST(LayoutFill, ComparisonCellsShowTheExactBodyFaintlyInGrey) {
  // methods_compare draws two of its three runs in cells (explicit Euler, RK4); each carries the exact
  // solution's body, translucent and grey (not the body's own colour), named in the frame's key.
  const scene::Scene s = shipped("methods_compare.toml");
  const double fps = s.render.output.fps;
  const long count = scene::frame_clock(s, fps).count();
  const auto runs = scene::simulate_runs(s, count, fps);
  ASSERT_EQ(runs.size(), 3u);
  ASSERT_EQ(runs[0].label, "euler");
  ASSERT_EQ(runs[1].label, "rk4");
  const compose::FrameBuilder fb(s, runs, fps, 320, 240);
  const viz::DrawList dl = fb.build(count / 2);
  ASSERT_EQ(dl.views.size(), 4u);  // two cells, the log plot and the momentum sphere
  for (std::size_t r = 0; r < 2; ++r) {
    const auto& sf = dl.views[r].surfaces;
    const auto ghosts = std::count_if(sf.begin(), sf.end(), [](const viz::SurfaceItem& x) { return x.name == "ghost"; });
    EXPECT_GT(ghosts, 0) << runs[r].label;
    for (const viz::SurfaceItem& x : sf) {
      if (x.name != "ghost") continue;
      EXPECT_LT(x.color.a, 0.5f) << runs[r].label;
      EXPECT_EQ(x.color, compose::kGhostColor) << runs[r].label;
      EXPECT_NE(x.color, sf.front().color) << "the ghost in the body's own colour tangles with it";
      // RK4's body lies on the ghost: drawn at the same depth, the two would show in stripes.
      EXPECT_TRUE(x.behind) << runs[r].label << ": the ghost z-fights the body it coincides with";
    }
    EXPECT_FALSE(sf.front().behind) << "the method's own body is drawn where it is";
  }
  // Explicit Euler has left the exact motion by then: its body and the ghost differ.
  const auto& euler = dl.views[0].surfaces;
  const auto ghost = std::find_if(euler.begin(), euler.end(), [](const viz::SurfaceItem& x) { return x.name == "ghost"; });
  ASSERT_NE(ghost, euler.end());
  EXPECT_NE(ghost->model, euler.front().model);
  const compose::FrameBuilder full(s, runs, fps, 1920, 1080);  // at 320x240 the frame key is too small to draw
  const auto& key = full.plan().frame_key;
  EXPECT_TRUE(std::any_of(key.begin(), key.end(), [](const viz::KeyEntry& e) {
    return e.text.find("exact solution") != std::string::npos && e.colors == std::vector<viz::Color>{compose::kGhostColor};
  }));
}

}  // namespace

namespace {

// The frame's lowest and highest view edges, frame px (y down).
std::pair<int, int> views_span(const FramePlan& p) {
  int top = 1 << 30, bottom = 0;
  for (const compose::ViewPlan& v : p.views) top = std::min(top, v.y), bottom = std::max(bottom, v.y + v.height);
  return {top, bottom};
}

}  // namespace

TEST(LayoutFill, ACaptionStripAtTheTopPutsTheViewsBelowIt) {
  FrameNeeds n = needs({view({0, 0, 1, 1})});
  n.caption_side = FrameNeeds::CaptionSide::top;
  const FramePlan p = compose::plan_frame(n);
  ASSERT_GT(p.captions.y1, p.captions.y0);
  EXPECT_EQ(p.captions.y0, 0) << "the strip is at the top";
  const auto [top, bottom] = views_span(p);
  EXPECT_GE(top, p.captions.y1 - 1) << "no view under the caption strip";
  EXPECT_NEAR(top, p.captions.y1, 1) << "the view starts where the strip ends";
  EXPECT_EQ(bottom, n.height) << "and fills the rest of the frame";
}

TEST(LayoutFill, AFrameKeyStripIsKeptFreeOfTheViews) {
  FrameNeeds n = needs({view({0, 0, 1, 1})});
  n.captions.clear();
  n.frame_key = {viz::key_entry(viz::Meaning::L, "L: angular momentum"),
                 viz::key_entry(viz::Meaning::omega, "omega: angular velocity")};
  const FramePlan p = compose::plan_frame(n);
  ASSERT_GT(p.frame_key_box.y1, p.frame_key_box.y0);
  EXPECT_EQ(p.frame_key_box.y1, n.height) << "without captions the frame key is at the foot";
  const auto [top, bottom] = views_span(p);
  EXPECT_EQ(top, 0);
  EXPECT_LE(bottom, p.frame_key_box.y0 + 1) << "no view under the frame key";
}

// Side views shorter than the frame leave the bottom-right corner free: the
// frame key stands there, and the main view keeps the views' whole height.
TEST(LayoutFill, AFrameKeyTakesAFreeCornerUnderTheSideViews) {
  FrameNeeds n = needs({view({0, 0, 0.66, 1}), view({0.66, 0, 0.34, 0.36}), view({0.66, 0.36, 0.34, 0.36})});
  n.captions.clear();
  n.frame_key = {viz::key_entry(viz::Meaning::L, "L: angular momentum"),
                 viz::key_entry(viz::Meaning::omega, "omega: angular velocity")};
  const FramePlan p = compose::plan_frame(n);
  ASSERT_GT(p.frame_key_box.y1, p.frame_key_box.y0);
  EXPECT_GE(p.frame_key_box.x0, 0.66f * float(n.width) - 1) << "in the corner, right of the main view";
  EXPECT_EQ(float(p.views[0].y + p.views[0].height), float(n.height)) << "the main view keeps the whole height";
  for (const compose::ViewPlan& v : p.views) {
    const bool apart = float(v.x + v.width) <= p.frame_key_box.x0 + 1 || float(v.y + v.height) <= p.frame_key_box.y0 + 1;
    EXPECT_TRUE(apart) << "a view under the key at " << v.x << ", " << v.y;
  }
  // A view in that corner: no corner, the strip across the frame as before.
  n.views.push_back(view({0.66, 0.72, 0.34, 0.28}));
  const FramePlan q = compose::plan_frame(n);
  EXPECT_EQ(q.frame_key_box.x0, 0);
  EXPECT_LT(float(q.views[0].y + q.views[0].height), float(n.height));
}

TEST(LayoutFill, EveryCaptionBackdropLiesInsideTheCaptionStrip) {
  // Text never sits on the content: each caption's backdrop, at its bottom
  // place, is inside the strip the views are kept out of.
  for (const auto& caption : {std::string("short"), std::string("a caption long enough to wrap onto a second line "
                                                                  "at this frame width, and then some more words")}) {
    FrameNeeds n = needs({view({0, 0, 1, 1})});
    n.captions = {caption};
    const FramePlan p = compose::plan_frame(n);
    ASSERT_GT(p.captions.y1, p.captions.y0);
    for (const viz::TextItem& t : viz::caption_items(caption, 1.0f, n.width, n.height, p.badge_side)) {
      if (t.backdrop.a <= 0) continue;
      EXPECT_GE(t.backdrop_px.y, p.captions.y0) << caption;
      EXPECT_LE(t.backdrop_px.w, p.captions.y1) << caption;
    }
    EXPECT_LE(views_span(p).second, p.captions.y0 + 1) << caption;
  }
}

namespace {

TEST(LayoutFill, AComparisonsPlotSitsUnderItsCellsAndNamesEachMethodInItsColour) {
  const scene::Scene s = shipped("methods_compare.toml");
  const double fps = s.render.output.fps;
  const long count = scene::frame_clock(s, fps).count();
  const auto runs = scene::simulate_runs(s, count, fps);
  ASSERT_EQ(runs.size(), 3u);
  const compose::FrameBuilder fb(s, runs, fps, 1920, 1080);
  const FramePlan& p = fb.plan();
  ASSERT_EQ(p.views.size(), 4u);  // [compare] cells: explicit Euler and RK4 (the exact body as their ghost); plot, sphere
  // arrange = "side": one row of tall cells, left to right, left of the views; the log plot over the momentum sphere.
  for (std::size_t r = 0; r < 2; ++r) {
    EXPECT_EQ(p.views[r].y, p.views[0].y) << r;
    if (r > 0) { EXPECT_GT(p.views[r].x, p.views[r - 1].x) << r; }
    for (std::size_t plot : {2u, 3u}) EXPECT_LE(p.views[r].x + p.views[r].width, p.views[plot].x + 1) << r;
    EXPECT_GE(p.views[r].height, p.views[2].height + p.views[3].height - 2) << "a cell the views' whole height";
  }
  EXPECT_EQ(p.views[2].x, p.views[3].x);  // stacked
  EXPECT_LT(p.views[2].y, p.views[3].y);
  EXPECT_GE(p.views[2].height, 300) << "a chart a hall can read";
  const viz::DrawList dl = fb.build(count - 1);
  ASSERT_EQ(dl.views.size(), 4u);
  ASSERT_EQ(dl.views[3].name, "momentum_sphere");
  std::map<std::string, viz::Color> cell_colour;  // each cell's title and readout share its method's colour
  for (std::size_t r = 0; r < 2; ++r) {
    const viz::TextItem* title = nullptr;
    int readouts = 0;  // the narrow cell's readout in two lines: t and dt, then ΔE/E
    for (const viz::TextItem& t : dl.views[r].texts) {
      if (t.name == "view_title") title = &t;
      if (t.name == "overlay") {
        ++readouts;
        EXPECT_LE(t.position_px.x + viz::text_width(t.text, t.size_px), float(p.views[r].width)) << t.text;
        ASSERT_NE(title, nullptr);
        EXPECT_EQ(t.color, title->color) << runs[r].label;
        EXPECT_GE(t.size_px, viz::text_px(viz::TextRole::view_title, 1080, 1) - 1e-3f) << "a readout a hall can read";
      }
    }
    ASSERT_NE(title, nullptr);
    EXPECT_EQ(readouts, 2) << runs[r].label;
    cell_colour[runs[r].label] = title->color;
    cell_colour[runs[r].title.substr(0, runs[r].title.find(','))] = title->color;  // as the plot names it
  }
  EXPECT_NE(cell_colour["euler"], cell_colour["rk4"]);
  // The plot: a curve per stepping method, named at its head as its cell names it and in its colour; no curve for
  // the exact solution.
  for (std::size_t plot : {2u}) {
    std::vector<std::string> named;
    for (const viz::TextItem& t : dl.views[plot].texts)
      if (t.name == "series_label") {
        named.push_back(t.text);
        EXPECT_EQ(t.color, cell_colour[t.text]) << t.text;
      }
    EXPECT_EQ(named.size(), 2u) << plot;
    EXPECT_EQ(std::count(named.begin(), named.end(), "exact"), 0) << plot;
    EXPECT_EQ(std::count(named.begin(), named.end(), "explicit Euler"), 1) << plot;
    EXPECT_EQ(std::count(named.begin(), named.end(), "RK4"), 1) << plot;
    // The flips ([draw] flips) marked on the time axis: five by 16 s (a mark under a level's note drawn in two pieces).
    std::set<double> marks;
    for (const viz::PolylineItem& l : dl.views[plot].polylines)
      if (l.name == "mark") marks.insert(l.points.front().x);
    EXPECT_EQ(marks.size(), 5u) << plot;
  }
}

}  // namespace
