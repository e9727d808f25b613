// Explanatory-video settings: the frame clock (time_scale, slow motion) and
// the loader's checks of [[views]], [[captions]], [title], [[slow_motion]].
#include <gtest/gtest.h>

#include "scene/frame_clock.hpp"
#include "scene/scene.hpp"
#include "scene_error.hpp"

namespace tumble::scene {
namespace {

TEST(FrameClock, WithoutScalingFrameKShowsExactlyKOverFps) {
  const FrameClock c(10, 30);
  EXPECT_EQ(c.count(), 301);
  for (long k : {0L, 1L, 7L, 299L, 300L}) EXPECT_EQ(c.time(k), static_cast<double>(k) / 30);
}

// The frames are 0 … count - 1: a time one frame past the last has no frame,
// however exactly it falls on the frame grid.
TEST(FrameClock, TheLastFrameIsCountMinusOneAndOnePastItIsNoFrame) {
  const FrameClock c(2, 10);
  ASSERT_EQ(c.count(), 21);
  EXPECT_EQ(c.frame_at(2.0), 20);
  EXPECT_EQ(c.frame_at(2.1), -1);
  EXPECT_EQ(c.frame_at(-0.1), -1);
  const FrameClock slow(2, 10, 0.5);  // 4 s of video: frames 0 … 40
  ASSERT_EQ(slow.count(), 41);
  EXPECT_EQ(slow.frame_at(2.0), 40);
  EXPECT_EQ(slow.frame_at(2.05), -1);
}

// The speed shown beside a slowed clock: whole fractions as ×1/n, the rest to 3 digits.
TEST(FrameClock, SpeedTextNamesWholeFractions) {
  EXPECT_EQ(speed_text(1.0), "");
  EXPECT_EQ(speed_text(0.25), "\u00d71/4");
  EXPECT_EQ(speed_text(0.1), "\u00d71/10");
  EXPECT_EQ(speed_text(0.3), "\u00d70.3");
  EXPECT_EQ(speed_text(2.0), "\u00d72");
}

TEST(FrameClock, QuarterTimeScaleIsFourTimesSlower) {
  const FrameClock c(2, 30, 0.25);
  EXPECT_EQ(c.count(), 241);  // 2 s simulated, 8 s of video at 30 fps
  EXPECT_DOUBLE_EQ(c.time(120), 1.0);
  EXPECT_DOUBLE_EQ(c.time(240), 2.0);
  EXPECT_EQ(c.frame_at(0.5), 60);
  EXPECT_EQ(c.frame_at(0.51), -1);
}

TEST(FrameClock, SlowMotionSegmentStretchesOnlyItsSpan) {
  // 1 s at full speed, [1, 2] at 0.1 (10 s of video), then 1 s at full speed.
  const FrameClock c(3, 10, 1.0, {{1.0, 2.0, 0.1}});
  EXPECT_EQ(c.count(), 121);  // 12 s of video
  EXPECT_DOUBLE_EQ(c.time(10), 1.0);
  EXPECT_DOUBLE_EQ(c.time(60), 1.5);
  EXPECT_DOUBLE_EQ(c.time(110), 2.0);
  EXPECT_DOUBLE_EQ(c.time(120), 3.0);
  EXPECT_DOUBLE_EQ(c.video_time(1.5), 6.0);
  for (long k = 1; k < c.count(); ++k) EXPECT_GT(c.time(k), c.time(k - 1));
}

const char* kBase = R"(
name = "x"
[simulation]
duration = 2.0
fps = 30
[[bodies]]
name = "racket"
shape = { type = "box", size = [3, 1, 0.4], resolution = 4, mass = 1 }
omega_body = [0.01, 5, 0.01]
)";

Scene load(const std::string& extra) { return load_scene_from_string(kBase + extra, "x.toml"); }

std::string error_of(const std::string& extra) { return scene_error(kBase + extra, "x.toml"); }

TEST(ExplainConfig, ReadsViewsCaptionsTitleAndSlowMotion) {
  const Scene s = load(R"(
[output]
time_scale = 0.5
[draw]
labels = true
overlay = ["time", "energy"]
[title]
text = "Flip"
hold = 2
[[views]]
kind = "world"
viewport = [0, 0, 0.5, 1]
[[views]]
kind = "plot"
body = "racket"
series = ["wbx", "axis2_L"]
viewport = [0.5, 0, 0.5, 1]
[[captions]]
start = 0.2
end = 1.0
text = "spin"
[[slow_motion]]
start = 1.0
end = 1.5
time_scale = 0.1
)");
  const ExplainConfig& e = s.render.explain;
  EXPECT_EQ(e.time_scale, 0.5);
  EXPECT_TRUE(e.labels);
  EXPECT_TRUE(s.render.draw.overlay_items.time && s.render.draw.overlay_items.energy);
  EXPECT_FALSE(s.render.draw.overlay_items.method || s.render.draw.overlay_items.step);
  EXPECT_FALSE(s.render.draw.overlay_items.state);  // only when named
  EXPECT_TRUE(load("[draw]\noverlay = [\"state\"]\n").render.draw.overlay_items.state);
  ASSERT_EQ(e.views.size(), 2u);
  EXPECT_EQ(e.views[1].kind, ViewKind::plot);
  EXPECT_EQ(e.views[1].series.size(), 2u);
  EXPECT_EQ((*e.views[1].viewport)[0], 0.5);
  ASSERT_EQ(e.captions.size(), 1u);
  EXPECT_EQ(e.captions[0].text, "spin");
  ASSERT_EQ(e.slow_motion.size(), 1u);
  EXPECT_EQ(e.title.text, "Flip");
  EXPECT_EQ(frame_clock(s, 30).count(), 1 + 30 * (2 + 1.0 / 0.5 + 0.5 / 0.1 + 0.5 / 0.5));  // hold, then the run
}

// A view's camera, the keys' switch and the principal-axis series.
TEST(ExplainConfig, ReadsViewCamerasKeysAndPrincipalSeries) {
  const Scene s = load(R"(
[draw]
key = false
[[views]]
kind = "momentum_sphere"
camera = { azimuth = 40, elevation = 10, distance = 6, follow = false }
[[views]]
kind = "plot"
)");
  const ExplainConfig& e = s.render.explain;
  EXPECT_FALSE(e.key);
  ASSERT_EQ(e.views.size(), 2u);
  EXPECT_EQ(e.views[0].camera.azimuth_deg, 40.0);
  EXPECT_EQ(e.views[0].camera.elevation_deg, 10.0);
  EXPECT_EQ(e.views[0].camera.distance, 6.0);
  EXPECT_EQ(e.views[0].camera.follow, false);
  EXPECT_EQ(e.views[1].series, (std::vector<std::string>{"w1", "w2", "w3"}));  // ω₁ ω₂ ω₃ by default
  EXPECT_TRUE(load("[[views]]\nkind = \"world\"\n").render.explain.key);   // keys on by default
  EXPECT_NE(error_of("[[views]]\nkind = \"plot\"\ncamera = { azimuth = 3 }\n").find("views[0].camera"),
            std::string::npos);
  EXPECT_NE(error_of("[[views]]\nkind = \"poinsot\"\ncamera = { elevation = 95 }\n").find("elevation"),
            std::string::npos);
  EXPECT_NE(error_of("[[views]]\nkind = \"body_frame\"\ncamera = { zoom = 2 }\n").find("zoom"), std::string::npos);
  // A body_frame camera fixed in principal axes (up), or across L, not both; a poinsot view takes no up.
  const auto bf = load("[[views]]\nkind = \"body_frame\"\ncamera = { up = [0, 0, 1], azimuth = 15, elevation = 25 }\n").render.explain.views;
  ASSERT_EQ(bf.size(), 1u);
  EXPECT_EQ(bf[0].camera.up, (std::array<double, 3>{0, 0, 1}));
  EXPECT_NE(error_of("[[views]]\nkind = \"body_frame\"\ncamera = { up = [0, 0, 1], across = \"-L\" }\n").find("not both"),
            std::string::npos);
  EXPECT_NE(error_of("[[views]]\nkind = \"poinsot\"\ncamera = { up = [0, 0, 1] }\n").find("up"), std::string::npos);
  // A world view draws its arrows thicker (line_scale) and may leave their names to the key (tip_names).
  const auto w = load("[[views]]\nkind = \"world\"\nline_scale = 2.5\ntip_names = false\n").render.explain.views;
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].line_scale, 2.5);
  EXPECT_FALSE(w[0].tip_names);
  EXPECT_TRUE(load("[[views]]\nkind = \"world\"\n").render.explain.views[0].tip_names);
  EXPECT_NE(error_of("[[views]]\nkind = \"poinsot\"\ntip_names = false\n").find("tip_names"), std::string::npos);
  EXPECT_NE(error_of("[[views]]\nkind = \"plot\"\nline_scale = 2\n").find("line_scale"), std::string::npos);
  // A plot of the energy error may draw the energies a fixed |L| allows; no other view or series.
  EXPECT_TRUE(load("[[views]]\nkind = \"plot\"\nseries = [\"energy_error\"]\nenergy_levels = true\n")
                  .render.explain.views[0]
                  .energy_levels);
  EXPECT_FALSE(load("[[views]]\nkind = \"plot\"\nseries = [\"energy_error\"]\n").render.explain.views[0].energy_levels);
  EXPECT_NE(error_of("[[views]]\nkind = \"plot\"\nenergy_levels = true\n").find("energy_error"), std::string::npos);
  EXPECT_NE(error_of("[[views]]\nkind = \"world\"\nenergy_levels = true\n").find("energy_levels"), std::string::npos);
}

TEST(ExplainConfig, ErrorsNameTheKeyAndWhatWasExpected) {
  EXPECT_NE(error_of("[[views]]\nkind = \"polar\"\n").find("views[0].kind"), std::string::npos);
  EXPECT_NE(error_of("[[views]]\nkind = \"world\"\nviewport = [0.6, 0, 0.5, 1]\n").find("x + width <= 1"),
            std::string::npos);
  EXPECT_NE(error_of("[[views]]\nkind = \"plot\"\nbody = \"rackett\"\n").find("did you mean \"racket\""),
            std::string::npos);
  EXPECT_NE(error_of("[[views]]\nkind = \"plot\"\nseries = [\"wq\"]\n").find("views[0].series"), std::string::npos);
  EXPECT_NE(error_of("[[captions]]\nstart = 1\nend = 0.5\ntext = \"a\"\n").find("end > start"), std::string::npos);
  EXPECT_NE(error_of("[[slow_motion]]\nstart = 0.5\nend = 1\n[[slow_motion]]\nstart = 0.8\nend = 1.2\n").find("overlaps"),
            std::string::npos);
  EXPECT_NE(error_of("[output]\ntime_scale = 0\n").find("output.time_scale"), std::string::npos);
  EXPECT_NE(error_of("[draw]\noverlay = [\"time\", \"fps\"]\n").find("draw.overlay"), std::string::npos);
  EXPECT_NE(error_of("[title]\nhold = 2\n").find("title.text"), std::string::npos);
}

}  // namespace
}  // namespace tumble::scene
