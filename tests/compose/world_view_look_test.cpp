// A world view's own look: `trail_axes` and `trails` (which axes' tips leave a
// trail there, how long), `box = false` (no principal-box outline there),
// `see_through`, `L_width`, `omega_width` and `trail_width`, as the demo's views use them.
#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>

#include "compose/frame_builder.hpp"
#include "scene/frame_clock.hpp"
#include "scene/frame_runs.hpp"
#include "scene/scene.hpp"
#include "viz/scene_view.hpp"

namespace tumble {
namespace {

int trails_of(const viz::View& v, int axis) {
  return static_cast<int>(std::count_if(v.polylines.begin(), v.polylines.end(), [&](const viz::PolylineItem& p) {
    return p.color == viz::kAxisColors[axis];
  }));
}

int outlines(const viz::View& v) {
  return static_cast<int>(std::count_if(v.boxes.begin(), v.boxes.end(), [](const viz::BoxItem& b) { return b.face.a == 0.0f; }));
}

TEST(WorldViewLook, TheDemosViewsTrailOnlyTheirSpinAxisAndDrawNoBox) {
  const scene::Scene s = scene::load_scene(std::filesystem::path(TUMBLE_SOURCE_DIR) / "scenes" / "dzhanibekov.toml");
  ASSERT_EQ(s.render.explain.views.size(), 3u);
  const double fps = s.render.output.fps;
  const scene::FrameClock clock = scene::frame_clock(s, fps);
  long k = 0;  // a second into the run: every trail has some length
  while (k + 1 < clock.count() && clock.time(k) < 1.0) ++k;
  const auto runs = scene::simulate_runs(s, k + 1, fps);
  const compose::FrameBuilder fb(s, runs, fps, 960, 540);
  const viz::DrawList dl = fb.build(k);
  ASSERT_EQ(dl.views.size(), 3u);
  // The main T (the stem's spin) trails only the stem's tip, draws no box, is
  // a little see-through (the stem seen behind the handle) and draws L thinner
  // than its axes; the views of the spins about e₁ and e₃ (by their body,
  // wherever they stand) only that axis' trail, and no box.
  for (std::size_t view = 0; view < 3; ++view) {
    const std::string& body = s.render.explain.views[view].body;
    const viz::View& v = dl.views[view];
    if (body == "t_handle") {
      for (int a = 0; a < 3; ++a) EXPECT_EQ(trails_of(v, a), a == 1 ? 1 : 0) << "main view, axis " << a;
      EXPECT_EQ(outlines(v), 0) << "no principal box";
      ASSERT_FALSE(v.surfaces.empty());
      for (const viz::SurfaceItem& sf : v.surfaces) EXPECT_LT(sf.color.a, 1.0f) << "see-through";
      double L = 0, axis = 1e9;
      for (const viz::ArrowItem& a : v.arrows) {
        if (a.name == "L") L = a.radius;
        else if (a.name.rfind('e', 0) == 0) axis = std::min(axis, a.radius);  // e1, e2, e3
      }
      EXPECT_GT(L, 0);
      EXPECT_LT(L, axis) << "L thinner than the axes";
      continue;
    }
    ASSERT_TRUE(body == "about_e1" || body == "about_e3") << body;
    const int spin = body == "about_e1" ? 0 : 2;
    for (int a = 0; a < 3; ++a) EXPECT_EQ(trails_of(v, a), a == spin ? 1 : 0) << body << " " << a;
    // The spin axis' trail bold and whole (not faded); L and ω thinner than the axes, the spin axis seen along them.
    for (const viz::PolylineItem& p : v.polylines)
      if (p.color == viz::kAxisColors[spin]) {
        EXPECT_GT(p.width_px, 2.0f) << body;
        EXPECT_FALSE(p.fade) << body;
      }
    double thin = 0, axis = 1e9;
    for (const viz::ArrowItem& a : v.arrows) {
      if (a.name == "L" || a.name == "omega") thin = std::max(thin, a.radius);
      else if (a.name.rfind('e', 0) == 0) axis = std::min(axis, a.radius);
    }
    EXPECT_GT(thin, 0) << body;
    EXPECT_LT(thin, axis) << body << ": L and ω thinner than the axes";
    EXPECT_EQ(outlines(v), 0) << body;
    EXPECT_FALSE(v.boxes.size() > 0 && v.surfaces.empty()) << "the body is still drawn";
  }
}

TEST(WorldViewLook, OnlyAWorldViewTakesTrailAxesAndBox) {
  const std::string base = "name = \"t\"\n[[bodies]]\nname = \"a\"\nshape = { type = \"box\", size = [0.3, 0.2, 0.1], resolution = [6, 4, 2], mass = 1 }\n"
                           "omega_body = [0, 1, 0]\n[draw]\nsurface = true\nbox = true\ntrails = 0.5\n";
  const scene::Scene ok = scene::load_scene_from_string(base + "[[views]]\nkind = \"world\"\nbody = \"a\"\ntrail_axes = [\"e2\"]\nbox = false\n", "v.toml");
  ASSERT_EQ(ok.render.explain.views.size(), 1u);
  EXPECT_EQ(ok.render.explain.views[0].trail_axes, (std::array<bool, 3>{false, true, false}));
  EXPECT_FALSE(ok.render.explain.views[0].box);
  EXPECT_FALSE(ok.render.explain.views[0].trail_seconds.has_value());  // [draw] trails
  EXPECT_FALSE(ok.render.explain.views[0].see_through);
  EXPECT_EQ(ok.render.explain.views[0].L_width, 1.0);
  EXPECT_EQ(ok.render.explain.views[0].omega_width, 1.0);
  EXPECT_EQ(ok.render.explain.views[0].trail_width, 1.0);
  auto error_of = [&](const std::string& view) {
    try {
      scene::load_scene_from_string(base + view, "v.toml");
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error_of("[[views]]\nkind = \"momentum_sphere\"\nbox = false\n").find("only a world view takes box"), std::string::npos);
  EXPECT_NE(error_of("[[views]]\nkind = \"plot\"\ntrail_axes = [\"e1\"]\n").find("only a world view takes trail_axes"), std::string::npos);
  EXPECT_NE(error_of("[[views]]\nkind = \"plot\"\ntrails = 2\n").find("only a world view takes trails"), std::string::npos);
  EXPECT_NE(error_of("[[views]]\nkind = \"plot\"\nsee_through = true\n").find("only a world view takes see_through"), std::string::npos);
  EXPECT_NE(error_of("[[views]]\nkind = \"plot\"\ntrail_width = 2\n").find("only a world view takes trail_width"), std::string::npos);
  const std::string bad = error_of("[[views]]\nkind = \"world\"\ntrail_axes = [\"e4\"]\n");
  EXPECT_NE(bad.find("v.toml:"), std::string::npos) << bad;
  EXPECT_NE(bad.find("expected items from"), std::string::npos) << bad;
}

}  // namespace
}  // namespace tumble
