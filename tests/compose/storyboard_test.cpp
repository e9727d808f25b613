// The storyboard's choice of frames and its sheet, GL-free: every event has
// its tile (flips at the first frame showing them, captions where fully
// shown, speed changes where they start), the spread covers the video, tiles
// and labels never overlap; and the layout's notes said once with their frames.
#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "compose/frame_builder.hpp"
#include "compose/layout_notes.hpp"
#include "compose/storyboard.hpp"
#include "scene/events.hpp"
#include "scene/frame_clock.hpp"
#include "scene/frame_runs.hpp"
#include "scene/scene.hpp"
#include "viz/captions.hpp"
#include "viz/text_layout.hpp"

namespace {

using namespace tumble;
using compose::StoryMoment;
using compose::StoryTile;

// A box spun near its intermediate axis (it flips several times in 8 s), a
// title card, slow motion around the first flip and two captions.
scene::Scene story_scene() {
  return scene::load_scene_from_string(
      "[simulation]\nmethod = \"exact\"\nduration = 8\nfps = 20\n"
      "[[bodies]]\nname = \"racket\"\nshape = { type = \"box\", size = [0.3, 0.1, 0.02], resolution = 4, mass = 1 }\n"
      "omega_body = [0.05, 5.0, 0.05]\n"
      "[output]\nwidth = 320\nheight = 180\ntime_scale = 0.5\n"
      "[title]\ntext = \"t\"\nhold = 1.0\n"
      "[[slow_motion]]\nstart = \"flip 1 - 0.2\"\nend = \"flip 1 + 0.2\"\ntime_scale = 0.125\n"
      "[[captions]]\nstart = 0.5\nend = \"flip 1\"\ntext = \"first\"\n"
      "[[captions]]\nstart = \"flip 2 - 0.5\"\nend = 8\ntext = \"second\"\n",
      "story.toml");
}

const StoryMoment* find(const std::vector<StoryMoment>& e, const std::string& why) {
  const auto it = std::find_if(e.begin(), e.end(), [&](const StoryMoment& m) { return m.why == why; });
  return it == e.end() ? nullptr : &*it;
}

TEST(Storyboard, EveryFlipHasTheFirstFrameShowingIt) {
  const scene::Scene s = story_scene();
  const scene::FrameClock clock = scene::frame_clock(s, s.render.output.fps);
  const std::vector<double> flips = scene::body_flip_times(s, 0);
  ASSERT_GE(flips.size(), 2u);
  const auto events = compose::story_events(s, clock, clock.count() - 1);
  for (std::size_t i = 0; i < flips.size(); ++i) {
    const StoryMoment* m = find(events, "flip " + std::to_string(i + 1));
    ASSERT_NE(m, nullptr) << "flip " << i + 1 << " at t = " << flips[i];
    // The frame shows the flip or just after it, and the frame before shows a time before it.
    EXPECT_GE(clock.time(m->frame), flips[i] - 1e-9);
    ASSERT_GT(m->frame, 0);
    EXPECT_LT(clock.time(m->frame - 1), flips[i]);
  }
}

TEST(Storyboard, CaptionsTitleCardAndSpeedChangesHaveTheirFrames) {
  const scene::Scene s = story_scene();
  const scene::FrameClock clock = scene::frame_clock(s, s.render.output.fps);
  const long last = clock.count() - 1;
  const auto events = compose::story_events(s, clock, last);
  const StoryMoment* title = find(events, "title card");
  ASSERT_NE(title, nullptr);
  EXPECT_EQ(title->frame, 0);
  // The animation starts at half speed where the card ends; slow motion where its stretch starts.
  const StoryMoment* start = find(events, "animation starts, \u00d71/2 slow motion");
  ASSERT_NE(start, nullptr);
  EXPECT_TRUE(clock.on_title_card(start->frame - 1));
  EXPECT_FALSE(clock.on_title_card(start->frame));
  const StoryMoment* slow = find(events, "\u00d71/8 slow motion");
  ASSERT_NE(slow, nullptr);
  EXPECT_DOUBLE_EQ(clock.rate(slow->frame), 0.125);
  EXPECT_NE(clock.rate(slow->frame - 1), 0.125);
  // Each caption's tile shows it fully, the frame before does not yet.
  const auto runs = scene::simulate_runs(s, clock.count(), clock.fps());
  const compose::FrameBuilder fb(s, runs, clock.fps(), 320, 180);
  for (int c = 1; c <= 2; ++c) {
    const StoryMoment* m = find(events, "caption " + std::to_string(c));
    ASSERT_NE(m, nullptr);
    auto alpha = [&](long k) {
      for (const auto& [i, a] : fb.captions_at(k))
        if (i == static_cast<std::size_t>(c - 1)) return a;
      return 0.0f;
    };
    EXPECT_FLOAT_EQ(alpha(m->frame), 1.0f) << "caption " << c;
    EXPECT_LT(alpha(m->frame - 1), 1.0f) << "caption " << c;
  }
  EXPECT_TRUE(std::is_sorted(events.begin(), events.end(),
                             [](const StoryMoment& a, const StoryMoment& b) { return a.frame < b.frame; }));
}

TEST(Storyboard, TilesAreTheSpreadAndEveryEventEachOnce) {
  const std::vector<StoryMoment> events{{0, "title card"}, {37, "flip 1"}, {50, "caption 1"}, {37, "caption 2"}};
  const std::vector<StoryTile> tiles = compose::story_tiles(events, 5, 100);
  std::vector<long> frames;
  for (const StoryTile& t : tiles) frames.push_back(t.frame);
  EXPECT_EQ(frames, (std::vector<long>{0, 25, 37, 50, 75, 100}));
  EXPECT_EQ(tiles[0].events, (std::vector<std::string>{"title card"}));
  EXPECT_EQ(tiles[2].events, (std::vector<std::string>{"flip 1", "caption 2"}));
  EXPECT_TRUE(tiles[1].events.empty());
  EXPECT_EQ(compose::story_tiles({}, 1, 100).size(), 1u);
  EXPECT_TRUE(compose::story_tiles({}, 0, 100).empty());
  EXPECT_EQ(compose::story_tiles(events, 0, 100).size(), 3u);  // the events only
}

TEST(Storyboard, SheetTilesAndLabelsNeverOverlapAndLabelsFitTheirStrip) {
  std::vector<compose::TileText> labels(7);
  for (std::size_t i = 0; i < labels.size(); ++i)
    labels[i] = {"frame " + std::to_string(i) + "   video 1.00 s   t = 0.500 s", i % 2 ? "flip 1 \u00b7 caption 2" : "",
                 i == 3 ? "\u201cA long caption that has to wrap under a narrow tile, over two or three lines at "
                          "least.\u201d"
                        : ""};
  const compose::SheetPlan p = compose::plan_sheet("a title", labels, 3, 240, 135);
  EXPECT_EQ(p.columns, 3);
  EXPECT_EQ(p.width, 3 * 240 + 4 * p.gap);
  EXPECT_EQ(p.height, p.header_h + 3 * (135 + p.label_h + p.gap));
  std::vector<viz::Box> boxes;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const glm::ivec2 a = p.tile_at(i);
    boxes.push_back({float(a.x), float(a.y), float(a.x + p.tile_w), float(a.y + p.tile_h + p.label_h)});
    EXPECT_GE(a.y, p.header_h);
    EXPECT_LE(a.x + p.tile_w, p.width);
    EXPECT_LE(a.y + p.tile_h + p.label_h, p.height);
    // Every line of the label lies in its strip (tile_w × label_h).
    for (const viz::TextItem& t : compose::tile_label(p, labels[i]).texts) {
      const viz::Box b = viz::text_box(t);
      EXPECT_GE(b.x0, 0) << t.text;
      EXPECT_LE(b.x1, float(p.tile_w)) << t.text;
      EXPECT_LE(b.y1, float(p.label_h)) << t.text;
      EXPECT_GE(t.size_px, 12.0f);
    }
  }
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j) EXPECT_FALSE(boxes[i].overlaps(boxes[j])) << i << " " << j;
  for (const viz::TextItem& t : compose::sheet_header(p, "a title").texts)
    EXPECT_LE(viz::text_box(t).y1, float(p.header_h));
}

TEST(LayoutNotes, EachNoteOnceWithItsFramesAsStretches) {
  compose::LayoutNotes n;
  for (long k = 0; k <= 9; ++k) n.add(k, {"key left out"});
  for (long k : {3L, 4L, 5L, 8L, 20L, 22L, 23L, 30L, 40L}) n.add(k, {"label 'e1' left out"});
  n.add(12, {});
  const std::vector<std::string> lines = n.lines();
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], "key left out (frames 0-9)");
  EXPECT_EQ(lines[1], "label 'e1' left out (frames 3-5, 8, 20, 22-23 and 2 more stretches)");
  compose::LayoutNotes one;
  one.add(7, {"x"});
  EXPECT_EQ(one.lines(), (std::vector<std::string>{"x (frame 7)"}));
}

// A key that cannot fit (its text under 8 px in a 300 px high frame) is a
// note of every frame, and check_layout (what `tumble info` prints) says so once.
TEST(LayoutNotes, CheckLayoutSaysWhatEveryFrameLeavesOut) {
  const scene::Scene s = scene::load_scene_from_string(
      "[simulation]\nmethod = \"exact\"\nduration = 1\nfps = 10\n"
      "[[bodies]]\nname = \"b\"\nshape = { type = \"box\", size = [0.3, 0.1, 0.02], resolution = 4, mass = 1 }\n"
      "omega_body = [0.05, 5.0, 0.05]\n"
      "[output]\nwidth = 400\nheight = 300\n"
      "[[views]]\nkind = \"momentum_sphere\"\ntitle = \"sphere\"\n",
      "small.toml");
  const std::vector<std::string> lines = compose::check_layout(s).lines();
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find("view 0 (momentum_sphere, 'sphere'): key left out"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("(frames 0-10)"), std::string::npos) << lines[0];
}

// A body name with no place in its small view is a note of each frame it is left out of.
TEST(LayoutNotes, ALabelLeftOutIsANoteOfItsFrames) {
  const scene::Scene s = scene::load_scene_from_string(
      "[simulation]\nmethod = \"exact\"\nduration = 1\nfps = 10\n"
      "[[bodies]]\nname = \"a_body_name_far_wider_than_its_view\"\n"
      "shape = { type = \"box\", size = [0.3, 0.1, 0.02], resolution = 4, mass = 1 }\n"
      "omega_body = [0.05, 5.0, 0.05]\n"
      "[output]\nwidth = 400\nheight = 300\n[draw]\nlabels = true\n"
      "[[views]]\nkind = \"world\"\nviewport = [0, 0, 0.3, 0.5]\n"
      "[[views]]\nkind = \"plot\"\nviewport = [0.3, 0, 0.7, 1]\n",
      "label.toml");
  const std::vector<std::string> lines = compose::check_layout(s).lines();
  const auto it = std::find_if(lines.begin(), lines.end(), [](const std::string& l) {
    return l.find("view 0 (world): label 'a_body_name_far_wider_than_its_view' left out") != std::string::npos;
  });
  ASSERT_NE(it, lines.end()) << (lines.empty() ? "no notes" : lines[0]);
  EXPECT_NE(it->find("(frames 0-10)"), std::string::npos) << *it;
}

}  // namespace
