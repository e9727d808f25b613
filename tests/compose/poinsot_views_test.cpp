// poinsot.toml's views, checked on the draw list (no GL): the Poinsot views
// and the view of the bodies in space look from one direction (so e₁ points
// the same way in an ellipsoid and in its box), and the body-fixed view draws
// the path of L's tip, ending at L's tip, with no name on its still body.
#include <filesystem>

#include <gtest/gtest.h>

#include "compose/frame_builder.hpp"
#include "compose/view_layout.hpp"
#include "scene/frame_clock.hpp"
#include "scene/frame_runs.hpp"
#include "scene/scene.hpp"
#include "viz/draw_list.hpp"
#include "viz/text_layout.hpp"

namespace {

namespace fs = std::filesystem;
using tumble::compose::FrameBuilder;

struct Lesson {
  tumble::scene::Scene scene = tumble::scene::load_scene(fs::path(TUMBLE_SOURCE_DIR) / "scenes" / "poinsot.toml");
  double fps = scene.render.output.fps;
  long frames = tumble::scene::frame_clock(scene, fps).count();
  std::vector<tumble::scene::Run> runs = tumble::scene::simulate_runs(scene, frames, fps);
};

glm::dvec3 eye(const tumble::viz::Camera& c) { return glm::normalize(c.position - c.target); }

TEST(PoinsotViews, EllipsoidsAndBoxesAreSeenFromOneDirection) {
  const Lesson l;
  const FrameBuilder fb(l.scene, l.runs, l.fps, 960, 540);
  for (const long k : {200L, 700L, 1500L}) {
    std::vector<tumble::viz::Camera> poinsot, world;
    for (const tumble::viz::View& v : fb.build(k).views) {
      if (v.name == "poinsot") poinsot.push_back(v.camera);
      if (v.name == "world") world.push_back(v.camera);
    }
    ASSERT_EQ(poinsot.size(), 2u);
    ASSERT_EQ(world.size(), 1u);
    for (const tumble::viz::Camera& c : poinsot) {
      EXPECT_GT(glm::dot(eye(c), eye(world[0])), 0.9999) << "frame " << k;
      EXPECT_GT(glm::dot(glm::normalize(c.up), glm::normalize(world[0].up)), 0.9999) << "frame " << k;
    }
  }
}

TEST(PoinsotViews, BodyFixedViewTracesLsTipAndNamesNoStillBody) {
  const Lesson l;
  const FrameBuilder fb(l.scene, l.runs, l.fps, 960, 540);
  int trails = 0;
  for (long k = 100; k < l.frames; k += 97)
    for (const tumble::viz::View& v : fb.build(k).views) {
      if (v.name != "body_frame") continue;
      for (const tumble::viz::TextItem& t : v.texts) EXPECT_NE(t.name.rfind("label:", 0), 0u) << t.name << " at " << k;
      const auto L = std::find_if(v.arrows.begin(), v.arrows.end(), [](const auto& a) { return a.name == "L"; });
      const auto trail = std::find_if(v.polylines.begin(), v.polylines.end(), [](const auto& p) { return p.name == "L_trail"; });
      ASSERT_NE(L, v.arrows.end());
      ASSERT_NE(trail, v.polylines.end()) << "frame " << k;
      ++trails;
      EXPECT_LT(glm::length(trail->points.back() - (L->origin + L->vector)), 1e-9) << "frame " << k;
      for (const glm::dvec3& p : trail->points)  // L keeps its length: every point as far from the centre as its tip
        EXPECT_NEAR(glm::length(p - L->origin), glm::length(L->vector), 1e-9) << "frame " << k;
    }
  EXPECT_GT(trails, 10);
}

// The boxes in space are small: their arrows are drawn 2.5 times as thick as
// the body-fixed view's (the same arrows, unscaled), and named by the key,
// not at their tips (bunched names there collided and flickered).
TEST(PoinsotViews, BoxesInSpaceHaveThickUnnamedArrows) {
  const Lesson l;
  const FrameBuilder fb(l.scene, l.runs, l.fps, 960, 540);
  for (const long k : {200L, 1000L}) {
    double world_e2 = 0, body_e2 = 0;
    for (const tumble::viz::View& v : fb.build(k).views) {
      if (v.name == "world") {
        for (const tumble::viz::TextItem& t : v.texts) EXPECT_NE(t.name.rfind("tip:", 0), 0u) << t.name << " at " << k;
        for (const tumble::viz::ArrowItem& a : v.arrows) world_e2 = a.name == "e2" ? a.radius : world_e2;  // the right box's, last
      }
      if (v.name == "body_frame")
        for (const tumble::viz::ArrowItem& a : v.arrows) body_e2 = a.name == "e2" ? a.radius : body_e2;
    }
    EXPECT_NEAR(world_e2, 2.5 * body_e2, 1e-12) << "frame " << k;
    EXPECT_GT(body_e2, 0) << "frame " << k;
  }
}

// Where a world point lands in the view's pixels (its content rectangle's camera).
glm::vec2 on_screen(const tumble::viz::View& v, const glm::dvec3& p) {
  const glm::vec4 c = v.content_px.value();
  const glm::vec2 size{c.z - c.x, c.w - c.y};
  const auto m = tumble::compose::camera_matrices(v.camera, size.x / size.y);
  const glm::vec4 clip = m.proj * m.view * glm::vec4(glm::vec3(p), 1.0f);
  return {c.x + (clip.x / clip.w + 1) * 0.5f * size.x, c.y + (1 - clip.y / clip.w) * 0.5f * size.y};
}

float distance_to(const tumble::viz::Box& b, glm::vec2 p) {
  return glm::length(p - glm::vec2(std::clamp(p.x, b.x0, b.x1), std::clamp(p.y, b.y0, b.y1)));
}

TEST(PoinsotViews, CurveNamesAreAtTheirCurvesOrLedToThem) {
  const Lesson l;
  const FrameBuilder fb(l.scene, l.runs, l.fps, 960, 540);
  int leaders = 0;
  for (const long k : {300L, 1000L, l.frames - 1})
    for (const tumble::viz::View& v : fb.build(k).views) {
      if (v.name != "poinsot") continue;
      for (const tumble::viz::TextItem& t : v.texts) {
        if (t.leader_to.empty()) continue;
        const auto curve = std::find_if(v.polylines.begin(), v.polylines.end(), [&](const auto& p) { return p.name == t.leader_to; });
        ASSERT_NE(curve, v.polylines.end()) << t.text << " at " << k;
        const tumble::viz::Box box = tumble::viz::text_box(t);
        float gap = 1e30f;  // from the label to its curve, on screen
        for (const glm::dvec3& p : curve->points) gap = std::min(gap, distance_to(box, on_screen(v, p)));
        if (gap < 0.4f * t.size_px) continue;  // at its curve
        // Else a leader in its colour: from the label's box to within a few px of the curve.
        bool led = false;
        for (const tumble::viz::PolylineItem& p : v.polylines) {
          if (!p.name.empty() || p.points.size() != 2 || p.color != t.color) continue;
          const glm::vec2 a = on_screen(v, p.points[0]), b = on_screen(v, p.points[1]);
          float end_gap = 1e30f;
          for (const glm::dvec3& q : curve->points) end_gap = std::min(end_gap, glm::length(b - on_screen(v, q)));
          led = led || (distance_to(box, a) < 1.5f && end_gap < 0.2f * t.size_px);
        }
        EXPECT_TRUE(led) << t.text << " " << gap << " px from its curve, with no leader, at frame " << k;
        leaders += led;
      }
    }
  EXPECT_GT(leaders, 0);
}

}  // namespace
