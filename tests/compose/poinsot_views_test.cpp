// poinsot.toml's views, checked on the draw list (no GL): the Poinsot views
// look from one direction, and the body-fixed view stands in the box's axes
// (e₂ across), draws L bold to a sphere round the box and the path of L's
// tip on it, ending at L's tip, with no name on its still body.
#include <algorithm>
#include <filesystem>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include "compose/frame_builder.hpp"
#include "compose/view_layout.hpp"
#include "scene/frame_clock.hpp"
#include "scene/frame_runs.hpp"
#include "scene/scene.hpp"
#include "viz/draw_list.hpp"
#include "viz/scene_view.hpp"
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

// Box 1, box 2 and box 1's close-up: one direction, one up; the close-up a narrower field.
TEST(PoinsotViews, EllipsoidsAreSeenFromOneDirection) {
  const Lesson l;
  const FrameBuilder fb(l.scene, l.runs, l.fps, 960, 540);
  for (const long k : {200L, 700L, 1500L}) {
    std::vector<tumble::viz::Camera> poinsot;
    for (const tumble::viz::View& v : fb.build(k).views)
      if (v.name == "poinsot") poinsot.push_back(v.camera);
    ASSERT_EQ(poinsot.size(), 3u);
    for (std::size_t i = 1; i < poinsot.size(); ++i) {
      EXPECT_GT(glm::dot(eye(poinsot[0]), eye(poinsot[i])), 0.9999) << "frame " << k << " view " << i;
      EXPECT_GT(glm::dot(glm::normalize(poinsot[0].up), glm::normalize(poinsot[i].up)), 0.9999) << "frame " << k;
    }
    EXPECT_LT(poinsot[2].fov_y_deg, 0.5 * poinsot[0].fov_y_deg) << "the close-up's field, frame " << k;
  }
}

// The tumbling box's own view stands as the box's principal axes do: +e₂
// towards the right, e₃ up, so L swings from one side to the other at a flip
// instead of pointing up at both ends of its swing (the old camera, across −L
// at t = 0, had −e₂ and +e₃ both up: dot(right, e₂) ≈ 0); the long axis e₁
// lies across the picture (to the left), not at the viewer, so the box reads long along e₁.
TEST(PoinsotViews, BoxViewHasE2AcrossAndE3Up) {
  const Lesson l;
  const FrameBuilder fb(l.scene, l.runs, l.fps, 960, 540);
  const std::size_t body = 1;  // "tumbling"
  ASSERT_EQ(l.scene.bodies[body].name, "tumbling");
  int seen = 0;
  // The last at t = 8 s, after flip 3.
  const long after_flip3 = static_cast<long>(tumble::scene::frame_clock(l.scene, l.fps).video_time(8.0) * l.fps);
  for (const long k : {200L, 700L, 1300L, after_flip3})  // 200: just after the title card
    for (const tumble::viz::View& v : fb.build(k).views) {
      if (v.name != "body_frame") continue;
      const Eigen::Quaterniond q = l.runs[0].frames[static_cast<std::size_t>(k)][body].q;  // world ← principal
      const glm::dvec3 e2 = tumble::viz::to_glm(q * Eigen::Vector3d::UnitY()), e3 = tumble::viz::to_glm(q * Eigen::Vector3d::UnitZ());
      const glm::dvec3 ahead = glm::normalize(v.camera.target - v.camera.position);
      const glm::dvec3 right = glm::normalize(glm::cross(ahead, v.camera.up));
      const glm::dvec3 up = glm::cross(right, ahead);
      const glm::dvec3 e1 = tumble::viz::to_glm(q * Eigen::Vector3d::UnitX());
      EXPECT_GT(glm::dot(right, e2), 0.5) << "frame " << k;   // +e₂ to the right, within 60° of across
      EXPECT_LT(glm::dot(right, e1), -0.7) << "frame " << k;  // e₁ to the left, within 45° of across
      EXPECT_GT(glm::dot(up, e3), 0.5) << "frame " << k;
      ++seen;
    }
  EXPECT_EQ(seen, 4);
}

// L is drawn bold from the box's centre out past the box, to a faint sphere
// (its radius is L's length), so its path lies on that sphere, outside the box.
TEST(PoinsotViews, BoxViewDrawsLBoldToASphereOutsideTheBox) {
  const Lesson l;
  const FrameBuilder fb(l.scene, l.runs, l.fps, 960, 540);
  const double box = tumble::viz::box_radius(l.scene.bodies[1].model);
  for (const long k : {200L, 1000L})
    for (const tumble::viz::View& v : fb.build(k).views) {
      if (v.name != "body_frame") continue;
      double L = 0, L_radius = 0, thickest_other = 0;
      for (const tumble::viz::ArrowItem& a : v.arrows)
        if (a.name == "L") L = glm::length(a.vector), L_radius = a.radius;
        else thickest_other = std::max(thickest_other, a.radius);
      EXPECT_GT(L, box) << "frame " << k;
      EXPECT_GT(L_radius, 1.3 * thickest_other) << "frame " << k;  // the boldest arrow (it was thinner than the axes)
      const auto sphere = std::find_if(v.surfaces.begin(), v.surfaces.end(), [](const auto& s) { return s.name == "L_sphere"; });
      ASSERT_NE(sphere, v.surfaces.end()) << "frame " << k;
      EXPECT_NEAR(glm::length(glm::dvec3(sphere->model[0])), L, 1e-9) << "frame " << k;
      EXPECT_LT(sphere->color.a, 0.25f) << "faint, frame " << k;
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
        // Else a thin grey leader (a textbook figure's): from the label's box to within a few px of the curve.
        bool starts = false, ends = false;
        const tumble::viz::Color leader = tumble::viz::color_of(tumble::viz::Meaning::ink, 0.7f);
        for (const tumble::viz::PolylineItem& p : v.polylines) {
          if (!p.name.empty() || p.points.size() != 2 || p.color != leader) continue;
          const glm::vec2 a = on_screen(v, p.points[0]), b = on_screen(v, p.points[1]);
          float end_gap = 1e30f;
          for (const glm::dvec3& q : curve->points) end_gap = std::min(end_gap, glm::length(b - on_screen(v, q)));
          starts = starts || distance_to(box, a) < 1.5f;
          ends = ends || end_gap < 0.2f * t.size_px;
        }
        const bool led = starts && ends;
        EXPECT_TRUE(led) << t.text << " " << gap << " px from its curve, with no leader, at frame " << k;
        leaders += led;
      }
    }
  EXPECT_GT(leaders, 0);
}

}  // namespace

namespace {

// Each Poinsot view draws the body the ellipsoid belongs to inside it: its
// surfaces (named "ellipsoid_body", translucent, in the body's colour) lie
// within the ellipsoid in every frame checked, their farthest vertex near
// its surface (the box fills it), and the box's long edge along e₁ (the
// ellipsoid's longest axis: the body turns with it).
TEST(PoinsotViews, EachEllipsoidHoldsItsBodyTurnedWithIt) {
  const Lesson l;
  const FrameBuilder fb(l.scene, l.runs, l.fps, 960, 540);
  int views = 0;
  const long after_flip3 = static_cast<long>(tumble::scene::frame_clock(l.scene, l.fps).video_time(8.0) * l.fps);  // t = 8 s, after flip 3
  for (const long k : {200L, 1300L, after_flip3}) {
    std::size_t poinsot = 0;
    for (const tumble::viz::View& v : fb.build(k).views) {
      if (v.name != "poinsot") continue;
      const std::size_t index = poinsot++;
      if (index == 2) {  // box 1's close-up: its curves and the contact point, no body, no arrows
        EXPECT_TRUE(std::none_of(v.surfaces.begin(), v.surfaces.end(), [](const auto& s) { return s.name == "ellipsoid_body"; }));
        EXPECT_TRUE(v.arrows.empty()) << "frame " << k;
        EXPECT_TRUE(std::any_of(v.points.begin(), v.points.end(), [](const auto& p) { return p.name == "contact_point"; }));
        EXPECT_TRUE(std::any_of(v.polylines.begin(), v.polylines.end(), [](const auto& p) { return p.name == "herpolhode"; }));
        continue;
      }
      const std::size_t body = index == 0 ? 0 : 1;  // box 1 ("stable"), box 2 ("tumbling")
      const Eigen::Quaterniond q = l.runs[0].frames[static_cast<std::size_t>(k)][body].q;
      const tumble::viz::SurfaceItem* ellipsoid = nullptr;
      std::vector<const tumble::viz::SurfaceItem*> inside;
      for (const tumble::viz::SurfaceItem& s : v.surfaces) {
        if (s.name == "ellipsoid") ellipsoid = &s;
        if (s.name != "ellipsoid_body") continue;
        inside.push_back(&s);
        EXPECT_LT(s.color.a, 1.0f) << "translucent";
      }
      ASSERT_TRUE(ellipsoid);
      ASSERT_FALSE(inside.empty()) << "frame " << k << " box " << body + 1;
      EXPECT_LT(inside.front() - v.surfaces.data(), ellipsoid - v.surfaces.data()) << "drawn before the glass";
      const glm::dmat4 to_unit = glm::inverse(ellipsoid->model);  // the ellipsoid is the unit sphere there
      double reach = 0;
      Eigen::Vector3d far = Eigen::Vector3d::Zero();
      for (const auto* s : inside)
        for (const glm::vec3& p : s->mesh->positions) {
          const glm::dvec3 w = glm::dvec3(s->model * glm::dvec4(glm::dvec3(p), 1.0));
          const double r = glm::length(glm::dvec3(to_unit * glm::dvec4(w, 1.0)));
          reach = std::max(reach, r);
          const Eigen::Vector3d body_axes = q.conjugate() * Eigen::Vector3d(w.x, w.y, w.z);  // principal axes
          if (body_axes.norm() > far.norm()) far = body_axes;
        }
      EXPECT_LE(reach, 1.0) << "frame " << k << " box " << body + 1;
      EXPECT_GT(reach, 0.85) << "frame " << k << " box " << body + 1;
      EXPECT_GT(std::abs(far.normalized().x()), 0.8) << "the farthest corner lies out along e₁";
      ++views;
    }
  }
  EXPECT_EQ(views, 6);
}

}  // namespace
