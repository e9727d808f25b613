// A figure built up while the animation waits: captions in turn inside one
// hold (`after`, `seconds` in video s) and a momentum sphere's `build_up`
// steps; each bad value an error at its place.
#include <gtest/gtest.h>

#include "scene/frame_clock.hpp"
#include "scene/scene.hpp"
#include "scene_error.hpp"

namespace tumble::scene {
namespace {

// A T-handle held 10 s of video at t = 0 (no title card): t = 0 is shown from video 0 to 10 s.
const char* kBase = R"(name = "build"
[simulation]
method = "exact"
duration = 6.0
fps = 30
[[bodies]]
name = "t_handle"
shape = { type = "t_handle", handle_length = 0.8, stem_length = 0.4, thickness = 0.1, resolution = 20, mass = 1.0 }
omega_body = [0.02, 8.0, 0.02]
[[holds]]
at = 0.0
hold = 10.0
[[views]]
kind = "momentum_sphere"
)";

Scene load(const std::string& extra) { return load_scene_from_string(kBase + extra, "build.toml"); }
std::string error_of(const std::string& extra) { return scene_error(kBase + extra, "build.toml"); }

TEST(BuildUp, CaptionsFollowOneAnotherInsideOneHold) {
  const Scene s = load(R"(build_up = { at = 0.0, seconds = [2, 2, 2, 2] }
[[captions]]
start = 0.0
seconds = 3.0
text = "one two three"
[[captions]]
start = 0.0
after = 3.0
seconds = 3.0
text = "four five six"
[[captions]]
start = 0.0
after = 6.0
end = 1.0
text = "seven eight nine"
)");
  EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();  // none overlap, each up long enough
  const FrameClock c = frame_clock(s, 30);
  const auto& caps = s.render.explain.captions;
  ASSERT_EQ(caps.size(), 3u);
  auto span = [&](std::size_t i) { return caption_video_span(c, caps[i]); };
  EXPECT_DOUBLE_EQ(span(0).first, 0.0);
  EXPECT_DOUBLE_EQ(span(0).second, 3.0);
  EXPECT_DOUBLE_EQ(span(1).first, 3.0);
  EXPECT_DOUBLE_EQ(span(1).second, 6.0);
  EXPECT_DOUBLE_EQ(span(2).first, 6.0);  // after the hold's start, up to the last frame showing t = 1 s
  EXPECT_NEAR(span(2).second, 10.0 + 1.0, 1e-9);
  // Without after/seconds a caption is as before: first frame showing start to the last showing end.
  const Scene plain = load("[[captions]]\nstart = 0.0\nend = 1.0\ntext = \"a b c\"\n");
  EXPECT_DOUBLE_EQ(caption_video_span(c, plain.render.explain.captions[0]).first, 0.0);
  EXPECT_NEAR(caption_video_span(c, plain.render.explain.captions[0]).second, 11.0, 1e-9);
  ASSERT_TRUE(s.render.explain.views[0].build_up);
  EXPECT_EQ(s.render.explain.views[0].build_up->seconds[3], 2.0);
}

TEST(BuildUp, CaptionsInTurnAreCheckedForReadingTimeAndOverlap) {
  // 10 words in 1 s of video; then a second caption starting inside the first.
  const Scene s = load(R"(
[[captions]]
start = 0.0
seconds = 1.0
text = "one two three four five six seven eight nine ten"
[[captions]]
start = 0.0
after = 0.5
seconds = 4.0
text = "a b c"
)");
  ASSERT_EQ(s.warnings.size(), 2u);
  EXPECT_NE(s.warnings[0].find("captions[0].text: up for 1.00 s of video (from 0.0 s of video after simulated 0)"),
            std::string::npos) << s.warnings[0];
  EXPECT_NE(s.warnings[1].find("captions[1].start: shown at the same time as captions[0] (video 0.5 s to 1.0 s)"),
            std::string::npos) << s.warnings[1];
}

TEST(BuildUp, BadValuesAreErrorsAtTheirPlace) {
  EXPECT_NE(error_of("[[captions]]\nstart = 0.0\nend = 1.0\nseconds = 2\ntext = \"a\"\n")
                .find("build.toml:18:11: error: captions[0].seconds: a caption ends at `end`"),
            std::string::npos)
      << error_of("[[captions]]\nstart = 0.0\nend = 1.0\nseconds = 2\ntext = \"a\"\n");
  EXPECT_NE(error_of("[[captions]]\nstart = 0.0\nafter = -1\nseconds = 2\ntext = \"a\"\n").find("captions[0].after"),
            std::string::npos);
  EXPECT_NE(error_of("build_up = { at = 0, seconds = [1, 2, 3] }\n").find("views[0].build_up.seconds: expected 4 video s"),
            std::string::npos)
      << error_of("build_up = { at = 0, seconds = [1, 2, 3] }\n");
  EXPECT_NE(error_of("build_up = { seconds = [1, 2, 3, 4] }\n").find("views[0].build_up.at: missing"), std::string::npos);
  EXPECT_NE(error_of("build_up = { at = 0, seconds = [1, 2, 0, 4] }\n").find("views[0].build_up.seconds[2]"),
            std::string::npos);
  EXPECT_NE(error_of("[[views]]\nkind = \"world\"\nbuild_up = { at = 0, seconds = [1, 2, 3, 4] }\n")
                .find("views[1].build_up: only a momentum_sphere view builds up its figure"),
            std::string::npos);
}

}  // namespace
}  // namespace tumble::scene
