// The event test: captions anchored to "flip N" follow the flip
// found from the simulation. The same scene with a different ω flips at
// another time; its caption is on screen at the new flip and gone 1 s after.
// GL-free: it reads the frames' draw lists.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "compose/frame_builder.hpp"
#include "scene/frame_runs.hpp"
#include "scene/events.hpp"
#include "scene/frame_clock.hpp"
#include "scene/scene.hpp"
#include "viz/draw_list.hpp"

namespace {

using tumble::scene::Scene;

const std::string kCaption = "the flip";

// A T-handle-like box spun about its intermediate axis y; `wobble` (rad/s)
// sets how long the spin stays near y before it flips.
Scene racket(double wobble, const std::string& start, const std::string& end) {
  const std::string w = std::to_string(wobble);
  return tumble::scene::load_scene_from_string(
      "[simulation]\nmethod = \"exact\"\nduration = 8\nfps = 20\n"
      "[[bodies]]\nname = \"racket\"\nshape = { type = \"box\", size = [0.3, 0.1, 0.02], resolution = 4, mass = 1 }\n"
      "omega_body = [" + w + ", 5.0, " + w + "]\n"
      "[output]\nwidth = 320\nheight = 180\n"
      "[[captions]]\nstart = " + start + "\nend = " + end + "\ntext = \"" + kCaption + "\"\n",
      "events.toml");
}

// Opacity of the caption `text` in frame k (0 when it is not drawn).
float caption_alpha(const Scene& s, long k, const std::string& text = kCaption) {
  const tumble::scene::FrameClock clock = tumble::scene::frame_clock(s, s.render.output.fps);
  const auto runs = tumble::scene::simulate_runs(s, clock.count(), clock.fps());
  const tumble::compose::FrameBuilder fb(s, runs, clock.fps(), 320, 180);
  for (const tumble::viz::TextItem& t : fb.build(k).texts)
    if (t.text == text) return t.color.a;
  return 0;
}

// The frame showing simulated time t (the nearest one).
long frame_of(const Scene& s, double t) {
  const tumble::scene::FrameClock clock = tumble::scene::frame_clock(s, s.render.output.fps);
  return std::lround(clock.video_time(t) * clock.fps());
}

TEST(CaptionEvents, CaptionFollowsTheFlipWhenOmegaChanges) {
  const Scene a = racket(0.001, "\"flip 1 - 0.3\"", "\"flip 1 + 0.5\"");
  const Scene b = racket(0.2, "\"flip 1 - 0.3\"", "\"flip 1 + 0.5\"");
  const double fa = tumble::scene::body_flip_times(a, 0).at(0), fb = tumble::scene::body_flip_times(b, 0).at(0);
  ASSERT_GT(std::abs(fa - fb), 1.0) << "the two spins must flip at clearly different times";
  ASSERT_LT(std::max(fa, fb) + 1, 8.0);
  for (const Scene* s : {&a, &b}) {
    const double f = s == &a ? fa : fb;
    EXPECT_NEAR(s->render.explain.captions[0].start, f - 0.3, 1e-9);
    EXPECT_GT(caption_alpha(*s, frame_of(*s, f)), 0.5f) << "caption not on screen at the flip, t = " << f;
    EXPECT_EQ(caption_alpha(*s, frame_of(*s, f + 1.0)), 0.0f) << "caption still on screen 1 s after the flip";
  }
  // Written in seconds at a's flip instead, the caption misses b's flip.
  const Scene fixed = racket(0.2, std::to_string(fa - 0.3), std::to_string(fa + 0.5));
  EXPECT_EQ(caption_alpha(fixed, frame_of(fixed, fb)), 0.0f);
}

// One caption followed by the next a moment later cuts to it: no frame between them is left without
// words (a fade out and a fade in would blank the frame for most of a second). One followed after a
// real gap still fades out.
TEST(CaptionEvents, ACaptionCutsToTheNextOneThatFollowsAtOnce) {
  const Scene s = tumble::scene::load_scene_from_string(
      "[simulation]\nmethod = \"exact\"\nduration = 8\nfps = 20\n"
      "[[bodies]]\nname = \"racket\"\nshape = { type = \"box\", size = [0.3, 0.1, 0.02], resolution = 4, mass = 1 }\n"
      "omega_body = [0.01, 5.0, 0.01]\n[output]\nwidth = 320\nheight = 180\n"
      "[[captions]]\nstart = 0.5\nend = 2.0\ntext = \"one\"\n"
      "[[captions]]\nstart = 2.05\nend = 4.0\ntext = \"two\"\n"
      "[[captions]]\nstart = 5.5\nend = 7.0\ntext = \"three\"\n",
      "cut.toml");
  for (double t = 1.5; t <= 3.0 + 1e-9; t += 0.05) {
    const long k = frame_of(s, t);
    EXPECT_EQ(caption_alpha(s, k, "one") + caption_alpha(s, k, "two"), 1.0f) << "t = " << t;
    EXPECT_EQ(caption_alpha(s, k, "one") * caption_alpha(s, k, "two"), 0.0f) << "both up at t = " << t;
  }
  EXPECT_LT(caption_alpha(s, frame_of(s, 3.95), "two"), 1.0f) << "a gap of 1.5 s follows: it fades out";
  EXPECT_LT(caption_alpha(s, frame_of(s, 5.55), "three"), 1.0f) << "it fades in";
}

}  // namespace
