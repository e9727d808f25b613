// The story tools of an explanatory video: the reading-time and overlap
// warnings, holds at an event, views that appear at anchored times, display
// names, caption positions, a plot's y-range, a world view's camera, the
// energy ellipsoid switch, and the legend refused where [[views]] have keys;
// each bad value an error at its file:line:col.
#include <gtest/gtest.h>

#include "scene/frame_clock.hpp"
#include "scene/scene.hpp"
#include "scene_error.hpp"

namespace tumble::scene {
namespace {

// A T-handle that flips at about 1.45 s and 4.2 s (tumble info).
const char* kBase = R"(name = "story"
[simulation]
method = "exact"
duration = 6.0
fps = 30
[[bodies]]
name = "t_handle"
shape = { type = "t_handle", handle_length = 0.8, stem_length = 0.4, thickness = 0.1, resolution = 20, mass = 1.0 }
omega_body = [0.02, 8.0, 0.02]
[[views]]
kind = "world"
)";

Scene load(const std::string& extra) { return load_scene_from_string(kBase + extra, "story.toml"); }
std::string error_of(const std::string& extra) { return scene_error(kBase + extra, "story.toml"); }

std::size_t count_with(const std::vector<std::string>& lines, const std::string& part) {
  return static_cast<std::size_t>(std::count_if(lines.begin(), lines.end(), [&](const std::string& l) {
    return l.find(part) != std::string::npos;
  }));
}

TEST(ReadingTime, ACaptionTooShortToReadIsWarnedAtItsLine) {
  // 15 words for 1 s of video: it needs 4.5 s at 0.3 s a word.
  const Scene s = load(R"(
[[captions]]
start = 0.5
end = 1.5
text = "Spun about its middle axis the handle seems steady but it is not at all"
)");
  ASSERT_EQ(count_with(s.warnings, "captions[0].text"), 1u) << (s.warnings.empty() ? "" : s.warnings[0]);
  const std::string& w = s.warnings[0];
  EXPECT_EQ(w.rfind("story.toml:16:8: warning: captions[0].text: up for 1.00 s of video", 0), 0u) << w;
  EXPECT_NE(w.find("15 words"), std::string::npos) << w;
  EXPECT_NE(w.find("4.5 s"), std::string::npos) << w;
}

TEST(ReadingTime, SlowMotionAndHoldsGiveTheTimeAndSilenceIt) {
  const std::string caption = R"(
[[captions]]
start = 0.5
end = 1.5
text = "Spun about its middle axis the handle seems steady but it is not at all"
)";
  EXPECT_EQ(count_with(load(caption + "[output]\ntime_scale = 0.2\n").warnings, "captions[0]"), 0u);  // 5 s of video
  EXPECT_EQ(count_with(load(caption + "[[holds]]\nat = 1.0\nhold = 3.6\n").warnings, "captions[0]"), 0u);
  EXPECT_EQ(count_with(load(caption + "[[holds]]\nat = 1.0\nhold = 3.0\n").warnings, "captions[0]"), 1u);  // 4.0 s < 4.5 s
}

TEST(ReadingTime, OverlappingCaptionsInOnePlaceAreWarned) {
  const std::string two = R"(
[[captions]]
start = 0.0
end = 3.0
text = "One."
[[captions]]
start = 2.5
end = 5.0
text = "Two."
)";
  const Scene s = load(two);
  ASSERT_EQ(count_with(s.warnings, "captions[1].start"), 1u);
  EXPECT_NE(s.warnings[0].find("same time as captions[0]"), std::string::npos) << s.warnings[0];
  // One caption strip: the captions agree on where it is.
  EXPECT_NE(error_of(two + "position = \"top\"\n").find("story.toml:21:12: error: captions[1].position: every caption shares one strip"),
            std::string::npos) << error_of(two + "position = \"top\"\n");
}

TEST(Holds, TheAnimationStopsAtTheEventForTheHold) {
  const Scene s = load("[[holds]]\nat = \"flip 1\"\nhold = 2.0\n");
  ASSERT_EQ(s.render.explain.holds.size(), 1u);
  const double flip = s.render.explain.holds[0].at;
  EXPECT_GT(flip, 1.0);
  const FrameClock c = frame_clock(s, 30);
  EXPECT_EQ(c.count(), 181 + 60);  // 6 s plus 2 s of video at 30 fps
  const double tau0 = c.video_time(flip);
  EXPECT_NEAR(tau0, flip, 1e-12);  // the run reaches the flip at its own speed, then stops
  int held = 0;
  for (long k = 0; k < c.count(); ++k) {
    const double tau = static_cast<double>(k) / 30;
    if (tau < tau0 - 1e-9) {
      EXPECT_LT(c.time(k), flip) << k;
    } else if (tau < tau0 + 2.0 - 1e-9) {
      EXPECT_DOUBLE_EQ(c.time(k), flip) << k;
      EXPECT_TRUE(c.in_hold(k)) << k;
      ++held;
    } else {
      EXPECT_GT(c.time(k), flip) << k;
      EXPECT_FALSE(c.in_hold(k)) << k;
    }
  }
  EXPECT_EQ(held, 60);
  EXPECT_NEAR(c.video_time_last(flip), flip + 2.0, 1e-12);  // a caption ending at the flip stays up through the hold
  EXPECT_NEAR(c.video_time_last(1.0), 1.0, 1e-12);
  EXPECT_NEAR(c.time(c.count() - 1), 6.0, 1e-9);
}

TEST(Holds, BadHoldsAreErrorsAtTheirPlace) {
  EXPECT_NE(error_of("[[holds]]\nat = \"flip 9\"\n").find("story.toml:13:6: error: holds[0].at"), std::string::npos);
  EXPECT_NE(error_of("[[holds]]\nat = 1.0\nhold = -1\n").find("holds[0].hold"), std::string::npos);
  EXPECT_NE(error_of("[[holds]]\nhold = 2\n").find("holds[0].at: missing"), std::string::npos);
  // Inside slow motion a hold stops the slowed animation as well.
  const FrameClock c = frame_clock(load("[[slow_motion]]\nstart = 1\nend = 2\ntime_scale = 0.1\n[[holds]]\nat = 1.5\nhold = 1\n"), 10);
  EXPECT_NEAR(c.video_time(1.5), 1 + 5, 1e-12);
  EXPECT_NEAR(c.video_time(2.0), 1 + 10 + 1, 1e-12);
  EXPECT_DOUBLE_EQ(c.time(65), 1.5);
  EXPECT_EQ(c.count(), 161);  // 1 + 10 + 1 + 4 s of video at 10 fps
}

TEST(Reveal, AViewAppearsAtItsAnchoredTime) {
  const Scene s = load("[[views]]\nkind = \"plot\"\nappear = \"flip 1 - 0.5\"\n");
  ASSERT_EQ(s.render.explain.views.size(), 2u);
  EXPECT_EQ(s.render.explain.views[0].appear, 0);
  EXPECT_GT(s.render.explain.views[1].appear, 0.5);
  EXPECT_EQ(s.render.explain.views[1].appear_text, "flip 1 - 0.5");
  EXPECT_NE(error_of("[[views]]\nkind = \"plot\"\nappear = \"later\"\n").find("story.toml:14:10: error: views[1].appear"),
            std::string::npos);
}

TEST(Reveal, AnEnergyEllipsoidFadesInFromItsAnchoredTime) {
  const Scene s = load("[[views]]\nkind = \"momentum_sphere\"\nellipsoid_from = \"flip 1 + 0.5\"\n");
  ASSERT_EQ(s.render.explain.views.size(), 2u);
  EXPECT_EQ(s.render.explain.views[0].ellipsoid_from, 0);
  EXPECT_GT(s.render.explain.views[1].ellipsoid_from, 1.5);  // flip 1 near 1.45 s, plus 0.5
  EXPECT_LT(s.render.explain.views[1].ellipsoid_from, 2.5);
  EXPECT_FALSE(s.render.explain.views[1].ellipsoid_opacity);
  EXPECT_TRUE(s.render.explain.views[1].level_arrows);
  EXPECT_FALSE(load("[[views]]\nkind = \"momentum_sphere\"\nlevel_arrows = false\n").render.explain.views[1].level_arrows);
  EXPECT_NE(error_of("level_arrows = false\n").find("only a momentum_sphere view draws level curves"), std::string::npos);
  EXPECT_EQ(s.render.explain.views[1].dot_scale, 1);
  EXPECT_FALSE(s.render.explain.views[1].dark_levels);
  const Scene hall = load("[[views]]\nkind = \"momentum_sphere\"\ndot_scale = 3\ndark_levels = true\n");
  EXPECT_EQ(hall.render.explain.views[1].dot_scale, 3);
  EXPECT_TRUE(hall.render.explain.views[1].dark_levels);
  EXPECT_NE(error_of("dot_scale = 3\n").find("only a momentum_sphere view takes dot_scale"), std::string::npos);
  EXPECT_NE(error_of("dark_levels = true\n").find("only a momentum_sphere view takes dark_levels"), std::string::npos);
  EXPECT_NE(error_of("[[views]]\nkind = \"momentum_sphere\"\ndot_scale = 9\n").find("views[1].dot_scale"), std::string::npos);
  EXPECT_EQ(*load("[[views]]\nkind = \"momentum_sphere\"\nellipsoid_opacity = 0.6\n").render.explain.views[1].ellipsoid_opacity, 0.6);
  EXPECT_EQ(s.render.explain.views[1].zoom, 1);
  EXPECT_EQ(load("[[views]]\nkind = \"momentum_sphere\"\nzoom = 1.2\n").render.explain.views[1].zoom, 1.2);
  EXPECT_NE(error_of("[[views]]\nkind = \"momentum_sphere\"\nzoom = 3\n").find("views[1].zoom"), std::string::npos);
  EXPECT_NE(error_of("zoom = 1.2\n").find("only a momentum_sphere view has a zoom"), std::string::npos);
  EXPECT_NE(error_of("[[views]]\nkind = \"momentum_sphere\"\nellipsoid_opacity = 2\n").find("views[1].ellipsoid_opacity"),
            std::string::npos);
  EXPECT_NE(error_of("ellipsoid_from = 1\n").find("only a momentum_sphere view draws an energy ellipsoid"), std::string::npos);
  // paths_of: bodies whose Π a sphere draws; a body's name, and on a sphere only.
  EXPECT_EQ(load("[[views]]\nkind = \"momentum_sphere\"\npaths_of = [\"t_handle\"]\n").render.explain.views[1].paths_of,
            std::vector<std::string>{"t_handle"});
  EXPECT_TRUE(s.render.explain.views[1].paths_of.empty());
  EXPECT_NE(error_of("paths_of = [\"t_handle\"]\n").find("only a momentum_sphere view takes paths_of"), std::string::npos);
  // close_up: a Poinsot view's contact region alone; on a Poinsot view only.
  EXPECT_FALSE(s.render.explain.views[1].close_up);
  EXPECT_TRUE(load("[[views]]\nkind = \"poinsot\"\nclose_up = true\n").render.explain.views[1].close_up);
  EXPECT_NE(error_of("[[views]]\nkind = \"momentum_sphere\"\nclose_up = true\n").find("only a poinsot view takes close_up"),
            std::string::npos);
  EXPECT_NE(error_of("[[views]]\nkind = \"momentum_sphere\"\npaths_of = [\"t_handel\"]\n").find("did you mean \"t_handle\""),
            std::string::npos);
  EXPECT_NE(error_of("[[views]]\nkind = \"momentum_sphere\"\npaths_of = []\n").find("views[1].paths_of"), std::string::npos);
  EXPECT_NE(error_of("[[views]]\nkind = \"momentum_sphere\"\nellipsoid_from = \"soon\"\n").find("story.toml:14:18: error: views[1].ellipsoid_from"),
            std::string::npos);
}

TEST(StorySettings, DisplayNamesMayHaveSpacesIdentifiersMayNot) {
  std::string text = kBase;
  const std::string anchor = "name = \"t_handle\"\n";
  text.insert(text.find(anchor) + anchor.size(), "display_name = \"the T-handle (wing nut)\"\n");
  const Scene s = load_scene_from_string(text, "story.toml");
  EXPECT_EQ(s.bodies[0].name, "t_handle");
  EXPECT_EQ(s.bodies[0].label, "the T-handle (wing nut)");
  EXPECT_EQ(load("").bodies[0].label, "t_handle");
  text.replace(text.find("the T-handle"), 12, "two\\nlines");
  EXPECT_NE(scene_error(text, "story.toml").find("story.toml:8:16: error: bodies[0].display_name"), std::string::npos)
      << scene_error(text, "story.toml");
}

TEST(StorySettings, CaptionPositionPlotRangeWorldCameraEllipsoid) {
  const Scene s = load(R"(camera = { position = [1, -2, 1], target = [0, 0, 0.1], fov_y = 30 }
[[views]]
kind = "plot"
y_range = [-10, 10]
[[views]]
kind = "momentum_sphere"
energy_ellipsoid = false
key = false
path = "trail"
line_scale = 1.5
levels = 6
[[captions]]
text = "Up here."
position = "top"
)");
  const auto& v = s.render.explain.views;
  ASSERT_EQ(v.size(), 3u);
  ASSERT_TRUE(v[0].camera.position);
  EXPECT_EQ((*v[0].camera.position)[1], -2);
  EXPECT_EQ(*v[0].camera.fov_y_deg, 30);
  ASSERT_TRUE(v[1].y_range);
  EXPECT_EQ((*v[1].y_range)[0], -10);
  EXPECT_FALSE(v[2].energy_ellipsoid);
  EXPECT_FALSE(v[2].key);
  EXPECT_TRUE(v[2].path_trail);
  EXPECT_EQ(v[2].line_scale, 1.5);
  EXPECT_EQ(v[2].levels, 6);
  EXPECT_FALSE(v[1].path_trail);
  EXPECT_EQ(v[1].line_scale, 1);
  EXPECT_TRUE(v[1].key);
  EXPECT_EQ(s.render.explain.captions[0].position, CaptionPosition::top);
}

TEST(StorySettings, MisplacedOrBadValuesAreErrorsAtTheirPlace) {
  EXPECT_NE(error_of("y_range = [1, 1]\n").find("only a plot view has a y_range"), std::string::npos);
  EXPECT_NE(error_of("[[views]]\nkind = \"plot\"\ny_range = [2, 1]\n").find("story.toml:14:11: error: views[1].y_range: expected low < high"),
            std::string::npos);
  EXPECT_NE(error_of("energy_ellipsoid = false\n").find("only a momentum_sphere view"), std::string::npos);
  EXPECT_NE(error_of("path = \"trail\"\n").find("only a momentum_sphere view takes path"), std::string::npos);
  EXPECT_NE(error_of("[[views]]\nkind = \"plot\"\nline_scale = 2\n").find("only a momentum_sphere or world view takes line_scale"),
            std::string::npos);
  EXPECT_NE(error_of("[[views]]\nkind = \"momentum_sphere\"\npath = \"all\"\n").find("views[1].path: expected \"polhode\", \"trail\" or \"trail_on_polhode\""),
            std::string::npos);
  EXPECT_NE(error_of("[draw]\ntrail_axes = [\"e4\"]\n").find("draw.trail_axes: expected items from"), std::string::npos);
  EXPECT_NE(error_of("[draw]\nflip_badge = 20\n").find("draw.flip_badge"), std::string::npos);
  EXPECT_NE(error_of("camera = { target = [0, 0, 0] }\n").find("views[0].camera.position: missing"), std::string::npos);
  EXPECT_NE(error_of("[[captions]]\ntext = \"x\"\nposition = \"middle\"\n").find("story.toml:14:12: error: captions[0].position"),
            std::string::npos);
  EXPECT_NE(error_of("[draw]\nlegend = true\n").find("story.toml:13:10: error: draw.legend"), std::string::npos);
  EXPECT_FALSE(load("").render.draw.legend);  // not drawn over the views' keys
}

TEST(StorySettings, ALogScaleOnPlotsOnly) {
  const Scene s = load("[[views]]\nkind = \"plot\"\nseries = [\"energy_error\"]\ny_scale = \"log\"\ny_range = [1e-10, 1.0]\n");
  ASSERT_EQ(s.render.explain.views.size(), 2u);
  EXPECT_TRUE(s.render.explain.views[1].y_log);
  EXPECT_FALSE(load("[[views]]\nkind = \"plot\"\ny_scale = \"linear\"\n").render.explain.views[1].y_log);
  EXPECT_NE(error_of("y_scale = \"log\"\n").find("story.toml:12:11: error: views[0].y_scale: only a plot view"), std::string::npos)
      << error_of("y_scale = \"log\"\n");
  EXPECT_NE(error_of("[[views]]\nkind = \"plot\"\ny_scale = \"ln\"\n").find("expected \"linear\" or \"log\", found \"ln\""),
            std::string::npos)
      << error_of("[[views]]\nkind = \"plot\"\ny_scale = \"ln\"\n");
  EXPECT_NE(error_of("[[views]]\nkind = \"plot\"\ny_scale = \"log\"\ny_range = [0, 1]\n").find("a log scale needs low > 0"),
            std::string::npos);
}

// A plot may leave its slow-motion stretches unshaded (the speed badge says it); other kinds refuse the key.
TEST(StorySettings, ShadeSpeedsOnPlotsOnly) {
  EXPECT_TRUE(load("[[views]]\nkind = \"plot\"\n").render.explain.views[1].shade_speeds);
  EXPECT_FALSE(load("[[views]]\nkind = \"plot\"\nshade_speeds = false\n").render.explain.views[1].shade_speeds);
  EXPECT_NE(error_of("shade_speeds = false\n").find("story.toml:12:16: error: views[0].shade_speeds: only a plot view"),
            std::string::npos)
      << error_of("shade_speeds = false\n");
}

// A momentum sphere's fixed camera may turn at an anchored time; other kinds, and a following camera, refuse it.
TEST(StorySettings, ASphereTurnsAtAnAnchoredTime) {
  const Scene s = load("[[views]]\nkind = \"momentum_sphere\"\nturn = { at = \"flip 1\", azimuth = 40, elevation = 30, seconds = 6 }\n");
  ASSERT_TRUE(s.render.explain.views[1].turn);
  const auto& t = *s.render.explain.views[1].turn;
  EXPECT_GT(t.at, 1.0);  // flip 1, about 1.45 s
  EXPECT_EQ(t.azimuth_deg, 40);
  EXPECT_EQ(t.elevation_deg, 30);
  EXPECT_EQ(t.seconds, 6);
  EXPECT_FALSE(load("[[views]]\nkind = \"momentum_sphere\"\n").render.explain.views[1].turn);
  EXPECT_NE(error_of("turn = { at = 1, azimuth = 0, elevation = 0, seconds = 1 }\n").find("story.toml:12:8: error: views[0].turn: only a momentum_sphere"),
            std::string::npos)
      << error_of("turn = { at = 1, azimuth = 0, elevation = 0, seconds = 1 }\n");
  EXPECT_NE(error_of("[[views]]\nkind = \"momentum_sphere\"\ncamera = { follow = true }\nturn = { at = 1, azimuth = 0, elevation = 0, seconds = 1 }\n")
                .find("a camera that follows Π does not turn"),
            std::string::npos);
  EXPECT_NE(error_of("[[views]]\nkind = \"momentum_sphere\"\nturn = { at = 1, azimuth = 0, elevation = 0 }\n").find("views[1].turn.seconds: missing"),
            std::string::npos)
      << error_of("[[views]]\nkind = \"momentum_sphere\"\nturn = { at = 1, azimuth = 0, elevation = 0 }\n");
}

// The same T-handle as a [compare] of two methods, without views.
std::string compare_scene(const std::string& extra) {
  std::string base = kBase;
  base.resize(base.find("[[views]]"));
  return base + "[compare]\nmethods = [\"euler\", \"exact\"]\n[draw]\nlegend = true\n" + extra;
}

TEST(StorySettings, AComparisonTakesPlotAndSphereViewsWithViewportsOnly) {
  const Scene s = load_scene_from_string(
      compare_scene("[[views]]\nkind = \"plot\"\nviewport = [0, 0.7, 1, 0.3]\nseries = [\"energy_error\"]\n"
                    "[[views]]\nkind = \"momentum_sphere\"\nviewport = [0, 0.5, 1, 0.2]\npath = \"trail\"\n"),
      "cmp.toml");
  ASSERT_EQ(s.render.explain.views.size(), 2u);
  EXPECT_EQ(s.render.compare_methods.size(), 2u);
  EXPECT_TRUE(s.render.draw.legend);  // the cells' legend stays: the plot has its own key
  for (const char* view : {"[[views]]\nkind = \"world\"\nviewport = [0, 0, 1, 0.5]\n", "[[views]]\nkind = \"plot\"\n",
                           "[[views]]\nkind = \"momentum_sphere\"\n"})
    EXPECT_NE(scene_error(compare_scene(view), "cmp.toml").find("with [compare], [[views]] may only add plots or momentum spheres, each with its viewport"),
              std::string::npos)
        << view;
}

TEST(StorySettings, AComparisonsCellsAreSomeOfItsMethods) {
  auto with_cells = [](const std::string& cells) {  // into [compare], before [draw]
    std::string text = compare_scene("");
    return text.replace(text.find("[draw]"), 0, cells);
  };
  EXPECT_EQ(load_scene_from_string(with_cells("cells = [\"euler\"]\n"), "cmp.toml").render.compare_cells,
            std::vector<Method>{Method::euler});
  EXPECT_TRUE(load_scene_from_string(compare_scene(""), "cmp.toml").render.compare_cells.empty()) << "unset: every method";
  for (const char* cells : {"cells = [\"rk4\"]\n", "cells = []\n", "cells = [\"euler\", \"euler\"]\n"}) {
    const std::string error = scene_error(with_cells(cells), "cmp.toml");
    EXPECT_NE(error.find("cmp.toml:"), std::string::npos) << cells;
    EXPECT_NE(error.find("compare.cells"), std::string::npos) << cells << error;
  }
}

TEST(StorySettings, AComparisonsCellsStandInARowOrBesideThePlots) {
  auto with_arrange = [](const std::string& arrange) {  // into [compare], before [draw]
    std::string text = compare_scene("");
    return text.replace(text.find("[draw]"), 0, "arrange = " + arrange + "\n");
  };
  EXPECT_EQ(load_scene_from_string(compare_scene(""), "cmp.toml").render.compare_arrange, CompareArrange::row) << "unset";
  EXPECT_EQ(load_scene_from_string(with_arrange("\"row\""), "cmp.toml").render.compare_arrange, CompareArrange::row);
  EXPECT_EQ(load_scene_from_string(with_arrange("\"side\""), "cmp.toml").render.compare_arrange, CompareArrange::side);
  for (const char* bad : {"\"left\"", "1", "[\"side\"]"}) {
    const std::string error = scene_error(with_arrange(bad), "cmp.toml");
    EXPECT_NE(error.find("cmp.toml:"), std::string::npos) << bad << error;
    EXPECT_NE(error.find("compare.arrange"), std::string::npos) << bad << error;
  }
  EXPECT_NE(scene_error(with_arrange("\"left\""), "cmp.toml").find("expected \"row\" or \"side\", found \"left\""),
            std::string::npos);
}

TEST(StorySettings, AComparisonsStepsAreItsFixedStepMethodsOwn) {
  auto with_steps = [](const std::string& steps, const std::string& methods = "[\"euler\", \"exact\"]") {
    const std::string usual = "[\"euler\", \"exact\"]";
    std::string text = compare_scene("");
    text.replace(text.find(usual), usual.size(), methods);
    return text.replace(text.find("[draw]"), 0, "steps = " + steps + "\n");
  };
  const Scene s = load_scene_from_string(with_steps("{ euler = 0.0025 }"), "cmp.toml");
  ASSERT_EQ(s.render.compare_steps.size(), 1u);
  EXPECT_EQ(s.render.compare_steps[0].first, Method::euler);
  EXPECT_EQ(s.render.compare_steps[0].second, 0.0025);
  EXPECT_TRUE(load_scene_from_string(compare_scene(""), "cmp.toml").render.compare_steps.empty()) << "unset: [simulation] dt";
  // Each refusal names the file, line and column and the key.
  const std::pair<std::string, std::string> bad[] = {
      {"{ rk4 = 0.0025 }", "compare.steps.rk4: unknown key"},       // not a compared method
      {"{ eulr = 0.0025 }", "did you mean 'euler'"},
      {"{ euler = 0 }", "compare.steps.euler: expected a finite number > 0"},
      {"{ euler = \"fast\" }", "compare.steps.euler"},
      {"0.0025", "compare.steps"},
      {"{ euler = 1e-9 }", "steps (duration / dt, the cap)"}};
  for (const auto& [steps, expected] : bad) {
    const std::string error = scene_error(with_steps(steps), "cmp.toml");
    EXPECT_NE(error.find("cmp.toml:"), std::string::npos) << steps << ": " << error;
    EXPECT_NE(error.find(expected), std::string::npos) << steps << ": " << error;
  }
  const std::string adaptive = scene_error(with_steps("{ rk45 = 0.01 }", "[\"euler\", \"rk45\"]"), "cmp.toml");
  EXPECT_NE(adaptive.find("compare.steps.rk45: method \"rk45\" is adaptive"), std::string::npos) << adaptive;
}

TEST(StorySettings, TimesPastTheRunsEndLeaveOutWhatTheyStart) {
  // As with --duration shorter than the scene's: the later text is left out, not an error.
  const Scene s = load(R"(
[[captions]]
start = 0.5
end = 9.0
text = "Up to the end."
[[captions]]
start = 7.0
text = "After the end."
[[holds]]
at = 6.5
hold = 1.0
)");
  ASSERT_EQ(s.render.explain.captions.size(), 1u);
  EXPECT_EQ(s.render.explain.captions[0].end, 6.0);
  EXPECT_TRUE(s.render.explain.holds.empty());
  EXPECT_EQ(count_with(s.warnings, "past the run's end (6 s): left out"), 3u);
  EXPECT_EQ(count_with(s.warnings, "story.toml:18:9: warning: captions[1].start: 7 s is past"), 1u)
      << (s.warnings.empty() ? "" : s.warnings[0]);
}

}  // namespace
}  // namespace tumble::scene
