// Bodies drawn as large as they are: a world view's camera is fitted on what
// it draws (a surface, not a hidden box) and centres it; the scene's text
// scale grows the small text and the layout still holds; a flip's badge stays
// up for a fixed stretch of running video.
#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>

#include "compose/frame_builder.hpp"
#include "compose/layout_report.hpp"
#include "scene/events.hpp"
#include "scene/frame_clock.hpp"
#include "scene/frame_runs.hpp"
#include "scene/scene.hpp"
#include "viz/draw_list.hpp"

namespace {

using tumble::compose::FrameBuilder;
using tumble::compose::LayoutItem;
using tumble::scene::simulate_runs;

// A T-handle drawn as its surface, nothing else: no box, no arrows, no text.
constexpr const char* kBare = R"(
name = "bare"
[simulation]
dt = 1e-3
duration = 1.0
fps = 10
[[bodies]]
name = "t_handle"
shape = { type = "t_handle", handle_length = 0.8, stem_length = 0.4, thickness = 0.1, resolution = 50, mass = 1.0 }
omega_body = [0.02, 8.0, 0.02]
[draw]
axes = false
overlay = false
legend = false
)";

const LayoutItem* find(const std::vector<LayoutItem>& items, const std::string& kind) {
  for (const LayoutItem& i : items)
    if (i.kind == kind) return &i;
  return nullptr;
}

// Only the surface decides where the camera goes: it is inside its content
// rectangle in every frame and, over the run, fills most of it in one
// direction. (Fitted on nothing, the camera came to a tenth of its distance
// and the handle overflowed the frame.)
TEST(BodyFit, ASurfaceWithNothingElseFillsItsViewAndStaysInIt) {
  const tumble::scene::Scene s = tumble::scene::load_scene_from_string(kBare, "bare.toml");
  const auto runs = simulate_runs(s, 11, 10);
  const FrameBuilder fb(s, runs, 10, 640, 360);
  float lo_x = 1e9f, lo_y = 1e9f, hi_x = -1e9f, hi_y = -1e9f;
  tumble::viz::Box content{};
  for (long k = 0; k < 11; ++k) {
    const std::vector<LayoutItem> items = tumble::compose::layout_items(fb.build(k), 640, 360);
    const LayoutItem* c = find(items, "content");
    const LayoutItem* f = find(items, "surface");
    ASSERT_TRUE(c && f) << "frame " << k;
    content = c->box;
    EXPECT_GE(f->box.x0, c->box.x0) << "frame " << k;
    EXPECT_GE(f->box.y0, c->box.y0) << "frame " << k;
    EXPECT_LE(f->box.x1, c->box.x1) << "frame " << k;
    EXPECT_LE(f->box.y1, c->box.y1) << "frame " << k;
    lo_x = std::min(lo_x, f->box.x0), lo_y = std::min(lo_y, f->box.y0);
    hi_x = std::max(hi_x, f->box.x1), hi_y = std::max(hi_y, f->box.y1);
  }
  const float fill = std::max((hi_x - lo_x) / (content.x1 - content.x0), (hi_y - lo_y) / (content.y1 - content.y0));
  EXPECT_GT(fill, 0.7f) << "the run's sweep fills its view";
  // Centred: as much room left on either side, in the direction it fills.
  const bool tall = (hi_y - lo_y) / (content.y1 - content.y0) >= (hi_x - lo_x) / (content.x1 - content.x0);
  const float before = tall ? lo_y - content.y0 : lo_x - content.x0, after = tall ? content.y1 - hi_y : content.x1 - hi_x;
  EXPECT_NEAR(before, after, 0.05f * (tall ? content.y1 - content.y0 : content.x1 - content.x0));
}

// [draw] text_scale grows every text of a laid-out frame but the captions and
// the title card, and the layout still finds room: nothing left out.
TEST(TextScale, GrowsTheSmallTextAndTheLayoutHolds) {
  const std::filesystem::path path = std::filesystem::path(TUMBLE_SOURCE_DIR) / "scenes/dzhanibekov_explained.toml";
  tumble::scene::Scene plain = tumble::scene::load_scene(path);
  plain.render.draw.text_scale = 1.0;  // the scene's own is 1.15: compare 1 with 1.25
  tumble::scene::Scene big = plain;
  big.render.draw.text_scale = 1.25;
  const double fps = plain.render.output.fps;
  const tumble::scene::FrameClock clock = tumble::scene::frame_clock(plain, fps);
  long k = 0;
  while (k + 1 < clock.count() && clock.time(k) < 0.3) ++k;
  const auto runs = simulate_runs(plain, k + 1, fps);
  const auto a = tumble::compose::layout_items(FrameBuilder(plain, runs, fps, 1920, 1080).build(k), 1920, 1080);
  const auto b = tumble::compose::layout_items(FrameBuilder(big, runs, fps, 1920, 1080).build(k), 1920, 1080);
  int grown = 0;
  for (const LayoutItem& i : a) {
    if (i.kind != "text" && i.kind != "key") continue;
    for (const LayoutItem& j : b) {
      if (j.name != i.name || j.text != i.text || j.kind != i.kind) continue;
      if (i.name == "caption") EXPECT_FLOAT_EQ(j.size_px, i.size_px) << "captions are sized for a hall already";
      else if (j.size_px >= 1.2f * i.size_px) ++grown;
      break;
    }
  }
  EXPECT_GE(grown, 8) << "view titles, overlay, tick and tip labels, key";
  for (const LayoutItem& i : b) EXPECT_NE(i.kind, "note") << i.text;
}

// The running-video frames from a flip's first frame in which its badge is up.
long badge_frames(const tumble::scene::Scene& s) {
  const double fps = s.render.output.fps;
  const tumble::scene::FrameClock clock = tumble::scene::frame_clock(s, fps);
  const double flip = tumble::scene::body_flip_times(s, 0).at(0);
  long first = 0;
  while (first < clock.count() && clock.time(first) < flip - 1e-9) ++first;
  const long last = std::min(first + 150, clock.count() - 1);
  const auto runs = simulate_runs(s, last + 1, fps);
  const FrameBuilder fb(s, runs, fps, 640, 360);
  auto badge = [&](long k) {
    for (const tumble::viz::TextItem& t : fb.build(k).texts)
      if (t.name == "speed") return t.text;
    return std::string();
  };
  EXPECT_EQ(badge(first - 1).find("flip"), std::string::npos);
  long running = 0;
  for (long k = first; k < last && badge(k).find("flip 1") != std::string::npos; ++k)
    if (!clock.in_hold(k)) ++running;
  return running;
}

// A flip's badge: up from the first frame showing the flip for 2 s of video
// in which the animation runs, whatever the speed (a hold does not use it up),
// or for [draw] flip_badge seconds: the demo's 1 s, so that the badge is up
// at a flip and not in the calm between flips 3.3 s apart.
TEST(Badge, AFlipIsMarkedForTwoSecondsOfRunningVideo) {
  const std::string t_handle = "[simulation]\nduration = 3\nfps = 30\n[[bodies]]\nname = \"t\"\n"
                               "shape = { type = \"t_handle\", handle_length = 0.8, stem_length = 0.4, thickness = 0.1, "
                               "resolution = 20, mass = 1.0 }\nomega_body = [0.02, 8.0, 0.02]\n"
                               "[[slow_motion]]\nstart = \"flip 1 - 0.3\"\nend = \"flip 1 + 0.3\"\ntime_scale = 0.25\n"
                               "[[holds]]\nat = \"flip 1 + 0.1\"\nhold = 1\n[draw]\nflips = true\n";
  EXPECT_EQ(badge_frames(tumble::scene::load_scene_from_string(t_handle, "t.toml")), 60);
  EXPECT_EQ(badge_frames(tumble::scene::load_scene_from_string(t_handle + "flip_badge = 0.5\n", "t.toml")), 15);
  const tumble::scene::Scene demo =
      tumble::scene::load_scene(std::filesystem::path(TUMBLE_SOURCE_DIR) / "scenes/dzhanibekov.toml");
  EXPECT_EQ(badge_frames(demo), std::lround(demo.render.explain.flip_badge_seconds * demo.render.output.fps));
  EXPECT_EQ(demo.render.explain.flip_badge_seconds, 0.5);  // the demo: gone well before the next flip
}

}  // namespace
