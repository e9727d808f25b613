// Times written as "flip N ± S", parsed, resolved at load from
// the body's own motion, and refused with file:line:col when malformed.
#include <gtest/gtest.h>

#include "scene/events.hpp"
#include "scene/frame_clock.hpp"
#include "scene/scene.hpp"
#include "scene_error.hpp"

namespace tumble::scene {
namespace {

TEST(EventTimes, ParsesFlipWithOptionalOffset) {
  const auto a = parse_event_time("flip 2");
  ASSERT_TRUE(a);
  EXPECT_EQ(a->flip, 2);
  EXPECT_EQ(a->offset, 0);
  const auto b = parse_event_time(" flip 1 -0.25 ");
  ASSERT_TRUE(b);
  EXPECT_EQ(b->flip, 1);
  EXPECT_EQ(b->offset, -0.25);
  const auto c = parse_event_time("flip 3 + 1e-1");
  ASSERT_TRUE(c);
  EXPECT_DOUBLE_EQ(c->offset, 0.1);
  for (const char* bad : {"flip", "flip 0", "flip -1", "flip 1 +", "flip 1 * 2", "flip1", "flop 1", "flip 1 + -2",
                          "flip 1 + 2 s", "1.5", "flip 1.5", "flip 1 + inf"})
    EXPECT_FALSE(parse_event_time(bad)) << bad;
}

const char* kBase = R"(name = "x"
[simulation]
method = "exact"
duration = 6.0
fps = 30
[[bodies]]
name = "racket"
shape = { type = "box", size = [0.3, 0.1, 0.02], resolution = 4, mass = 1 }
omega_body = [0.02, 5, 0.02]
[[bodies]]
name = "still"
shape = { type = "box", size = [0.3, 0.1, 0.02], resolution = 4, mass = 1 }
position = [1, 0, 0]
omega_body = [0, 0, 3]
)";

std::string error_of(const std::string& extra) { return scene_error(kBase + extra, "x.toml"); }

TEST(EventTimes, CaptionsAndSlowMotionResolveToTheBodysFlips) {
  const Scene s = load_scene_from_string(kBase + std::string(R"(
[[captions]]
start = "flip 1 - 0.5"
end = "flip 2"
text = "a"
[[slow_motion]]
start = "flip 1 - 0.2"
end = "flip 1 + 0.2"
time_scale = 0.1
)"), "x.toml");
  const std::vector<double> flips = body_flip_times(s, 0);
  ASSERT_GE(flips.size(), 2u);
  const Caption& c = s.render.explain.captions.at(0);
  EXPECT_DOUBLE_EQ(c.start, flips[0] - 0.5);
  EXPECT_DOUBLE_EQ(c.end, flips[1]);
  EXPECT_EQ(c.start_text, "flip 1 - 0.5");
  EXPECT_DOUBLE_EQ(s.render.explain.slow_motion.at(0).start, flips[0] - 0.2);
  // A pure spin about the largest axis keeps Π₂ = 0: it never flips.
  EXPECT_TRUE(body_flip_times(s, 1).empty());
}

TEST(EventTimes, BadTimesAreErrorsAtTheirPosition) {
  const std::string bad = error_of("[[captions]]\nstart = \"flip one\"\ntext = \"a\"\n");
  EXPECT_NE(bad.find("x.toml:16:9: error: captions[0].start: expected simulated seconds"), std::string::npos) << bad;
  EXPECT_NE(bad.find("found the string \"flip one\""), std::string::npos) << bad;
  const std::string none = error_of("[[captions]]\nbody = \"still\"\nstart = \"flip 1\"\ntext = \"a\"\n");
  EXPECT_NE(none.find("captions[0].start: body 'still' flips 0 time(s) in 6 s; there is no flip 1"),
            std::string::npos)
      << none;
  const std::string after = error_of("[[captions]]\nstart = \"flip 1 + 0.1\"\nend = \"flip 1\"\ntext = \"a\"\n");
  EXPECT_NE(after.find("captions[0].end: expected end > start"), std::string::npos) << after;
  EXPECT_NE(error_of("[[captions]]\nbody = \"rackett\"\nstart = \"flip 1\"\ntext = \"a\"\n").find("did you mean"),
            std::string::npos);
  EXPECT_NE(error_of("[title]\ntext = \"T\"\nduration = 2\n").find("title.duration: renamed to hold"),
            std::string::npos);
}

TEST(EventTimes, TitleHoldDelaysTheAnimation) {
  const Scene s = load_scene_from_string(kBase + std::string("[title]\ntext = \"T\"\nhold = 2\n"), "x.toml");
  const FrameClock clock = frame_clock(s, 30);
  EXPECT_EQ(clock.count(), 60 + 181);
  EXPECT_TRUE(clock.on_title_card(59));
  EXPECT_FALSE(clock.on_title_card(60));
  EXPECT_EQ(clock.time(59), 0.0);
  EXPECT_EQ(clock.rate(59), 0.0);
  EXPECT_DOUBLE_EQ(clock.time(90), 1.0);
  EXPECT_DOUBLE_EQ(clock.video_time(1.0), 3.0);
  EXPECT_EQ(clock.frame_at(0.0), 60);
}

}  // namespace
}  // namespace tumble::scene
