// What the lessons draw, checked on the draw list (no GL): every momentum
// sphere labels each end of ±e₁, ±e₂, ±e₃ that the ball does not hide, at its
// own tip, in every frame of every shipped scene that has one; a generated shape is drawn at the size the scene
// declares (not its lattice's extent); a body_frame view shows its own body
// only; the ground grid stays put.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "compose/frame_builder.hpp"
#include "scene/frame_runs.hpp"
#include "scene/frame_clock.hpp"
#include "scene/scene.hpp"
#include "viz/captions.hpp"
#include "viz/draw_list.hpp"
#include "viz/sphere_camera.hpp"
#include "viz/sphere_figure.hpp"
#include "viz/text_layout.hpp"

namespace {

namespace fs = std::filesystem;
using tumble::compose::FrameBuilder;
using tumble::scene::simulate_runs;

std::vector<fs::path> sphere_scenes() {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(fs::path(TUMBLE_SOURCE_DIR) / "scenes")) {
    if (e.path().extension() != ".toml") continue;
    std::ifstream in(e.path());
    std::stringstream text;
    text << in.rdbuf();
    if (text.str().find("\"momentum_sphere\"") != std::string::npos) out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The axis end `name` ("axis_label_-e3") in units of |L|.
glm::dvec3 axis_end(const std::string& name) {
  glm::dvec3 e(0);
  e[name.back() - '1'] = (name.find("_-e") != std::string::npos ? -1 : 1) * tumble::viz::kAxisReach;
  return e;
}

TEST(LessonFigures, EverySphereLabelsEachVisibleAxisEndAtItsTipInEveryFrame) {
  const std::vector<fs::path> scenes = sphere_scenes();
  ASSERT_GE(scenes.size(), 2u);  // dzhanibekov_explained, tennis_racket
  const char* const kNames[] = {"axis_label_e1", "axis_label_e2", "axis_label_e3",
                                "axis_label_-e1", "axis_label_-e2", "axis_label_-e3"};
  for (const fs::path& p : scenes)
    for (const auto& [w, h] : {std::pair{640, 360}, std::pair{960, 540}, std::pair{1920, 1080}}) {
      const tumble::scene::Scene s = tumble::scene::load_scene(p);
      const double fps = s.render.output.fps;
      const long frames = tumble::scene::frame_clock(s, fps).count();
      const auto runs = simulate_runs(s, frames, fps);
      const FrameBuilder fb(s, runs, fps, w, h);
      int spheres = 0;
      for (long k = 0; k < frames; ++k) {
        if (fb.clock().on_title_card(k)) continue;
        for (const tumble::viz::View& v : fb.build(k).views) {
          if (v.name != "momentum_sphere") continue;
          ++spheres;
          const float vw = static_cast<float>(v.viewport->z * w), vh = static_cast<float>(v.viewport->w * h);
          // The camera sees through the content rectangle (a key beside it narrows it); texts are in the view's px.
          const glm::vec4 c = v.content_px.value_or(glm::vec4(0, 0, vw, vh));
          const tumble::viz::ViewportProjection project(v.camera, c.z - c.x, c.w - c.y);
          for (const char* name : kNames) {
            const auto it = std::find_if(v.texts.begin(), v.texts.end(), [&](const auto& t) { return t.name == name; });
            const bool hidden = tumble::viz::hidden_by_ball(v.camera.position, axis_end(name), 1.0);
            EXPECT_FALSE(hidden && it != v.texts.end()) << p.filename() << " frame " << k << ": " << name << " named behind the ball";
            if (hidden) continue;  // pointing away, behind the ball: nothing of it shows
            ASSERT_NE(it, v.texts.end()) << p.filename() << " " << w << "x" << h << " frame " << k << ": no " << name;
            const tumble::viz::Box b = tumble::viz::text_box(*it);
            EXPECT_TRUE(b.x0 >= 0 && b.y0 >= 0 && b.x1 <= vw && b.y1 <= vh)
                << p.filename() << " frame " << k << ": " << name << " leaves its view";
            // On its own pole: the box within three label heights of the end's tip as drawn (past the
            // arrowhead, and moved off a curve it would sit on); a label at the rim was six and more away.
            glm::vec2 tip;
            ASSERT_TRUE(project(axis_end(name), tip));
            tip += glm::vec2(c.x, c.y);
            const float dx = std::max({b.x0 - tip.x, 0.0f, tip.x - b.x1}), dy = std::max({b.y0 - tip.y, 0.0f, tip.y - b.y1});
            EXPECT_LE(std::hypot(dx, dy), 3.0f * it->size_px)
                << p.filename() << " " << w << "x" << h << " frame " << k << ": " << name << " is " << std::hypot(dx, dy)
                << " px from its tip";
          }
        }
      }
      EXPECT_GT(spheres, 0) << p.filename();
    }
}

// dzhanibekov_explained's sphere turns slowly in its end hold (its view's
// `turn`): from where it stood when the hold began to the turn's direction, a
// little each frame, and then stands; the loops round ±e₁ are seen open, not edge-on.
TEST(LessonFigures, TheSphereTurnsSlowlyInTheEndHold) {
  const tumble::scene::Scene s = tumble::scene::load_scene(fs::path(TUMBLE_SOURCE_DIR) / "scenes" / "dzhanibekov_explained.toml");
  const auto turn_of = std::find_if(s.render.explain.views.begin(), s.render.explain.views.end(),
                                    [](const auto& v) { return v.turn.has_value(); });
  ASSERT_NE(turn_of, s.render.explain.views.end());
  const auto& turn = *turn_of->turn;
  const double fps = s.render.output.fps;
  const tumble::scene::FrameClock clock = tumble::scene::frame_clock(s, fps);
  const auto runs = simulate_runs(s, clock.count(), fps);
  const FrameBuilder fb(s, runs, fps, 960, 540);
  auto eye = [&](long k) {
    for (const tumble::viz::View& v : fb.build(k).views)
      if (v.name == "momentum_sphere") return glm::normalize(v.camera.position - v.camera.target);
    ADD_FAILURE() << "no sphere in frame " << k;
    return glm::dvec3(0);
  };
  const long k0 = std::lround(clock.video_time(turn.at) * fps), k1 = k0 + std::lround(turn.seconds * fps);
  ASSERT_LT(k1, clock.count());
  const double az = glm::radians(turn.azimuth_deg), el = glm::radians(turn.elevation_deg);
  const glm::dvec3 target{std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
  EXPECT_LT(glm::dot(eye(k0), target), 0.9);             // it starts elsewhere
  EXPECT_NEAR(glm::dot(eye(k1), target), 1.0, 1e-9);     // and ends there
  // It stands there to its last frame (the view's `until`: the closing side by side follows).
  long last = k1;
  while (last + 1 < clock.count() && clock.time(last + 1) < turn_of->until) ++last;
  EXPECT_NEAR(glm::dot(eye(last), target), 1.0, 1e-9);
  double widest = 0;
  for (long k = k0; k < k1; ++k) widest = std::max(widest, std::acos(std::min(1.0, glm::dot(eye(k), eye(k + 1)))));
  EXPECT_LT(glm::degrees(widest), 1.0);  // slowly: under 1° a frame
  // At the end, e₁ is at least 30° from edge-on (its loops open).
  EXPECT_GT(std::abs(target.x), std::sin(glm::radians(30.0)));
}

// [draw] tip_names_further: on dzhanibekov_explained's T-handle some arrow tips
// lie on the handle in some frames (every 15th frame of the video is looked
// at, 960×540); without it their names are left out there, with it they are
// drawn a line or two further out, and no name is ever lost.
TEST(LessonFigures, TipNamesFurtherOutNameTipsOnTheHandle) {
  const tumble::scene::Scene s = tumble::scene::load_scene(fs::path(TUMBLE_SOURCE_DIR) / "scenes" / "dzhanibekov_explained.toml");
  ASSERT_TRUE(s.render.draw.tip_names_further);
  const double fps = s.render.output.fps;
  const long count = tumble::scene::frame_clock(s, fps).count();
  const auto runs = simulate_runs(s, count, fps);
  tumble::scene::Scene plain = s;
  plain.render.draw.tip_names_further = false;
  const FrameBuilder further_out(s, runs, fps, 960, 540), at_tips(plain, runs, fps, 960, 540);
  auto names = [&](bool further, long k) {
    std::set<std::string> out;
    for (const tumble::viz::View& v : (further ? further_out : at_tips).build(k).views)
      for (const tumble::viz::TextItem& t : v.texts)
        if (t.name.rfind("tip:", 0) == 0) out.insert(t.name);
    return out;
  };
  int gained = 0;
  for (long k = 0; k < count; k += 15) {
    const std::set<std::string> with = names(true, k), without = names(false, k);
    for (const std::string& n : without) EXPECT_TRUE(with.count(n)) << n << " lost in frame " << k;
    gained += with.size() > without.size();
  }
  EXPECT_GT(gained, 0) << "no frame where a tip on the handle needs its name further out";
}

// A phone: 75.8 × 160.8 × 7.8 mm, three lattice cells through its thickness
// (whose particles span only 5.2 mm of it), tilted so that world and body axes differ.
const char* kPhone = R"(
[simulation]
method = "exact"
duration = 1.0
fps = 10
[[bodies]]
name = "phone"
shape = { type = "box", size = [0.0758, 0.1608, 0.0078], resolution = [8, 16, 3], mass = 0.2 }
orientation = [0.9, 0.3, 0.2, 0.1]
position = [0.1, -0.2, 0.3]
omega_body = [0.1, 9, 0.1]
[draw]
axes = false
)";

TEST(LessonFigures, GeneratedBoxIsDrawnAtItsDeclaredSize) {
  const tumble::scene::Scene s = tumble::scene::load_scene_from_string(kPhone, "phone.toml");
  const auto runs = simulate_runs(s, 11, 10);
  const FrameBuilder fb(s, runs, 10, 640, 360);
  for (long k : {0L, 7L}) {
    const tumble::viz::DrawList dl = fb.build(k);
    ASSERT_EQ(dl.views.size(), 1u);
    const tumble::viz::View& v = dl.views[0];
    ASSERT_EQ(v.surfaces.size(), 1u) << "frame " << k << ": the box is not drawn as a surface";
    EXPECT_TRUE(v.boxes.empty());  // the principal box only when asked for
    // The surface's corners in the body's cloud axes: the world state's orientation undone.
    const tumble::BodyState& st = runs[0].frames[static_cast<std::size_t>(k)][0];
    const tumble::scene::Body& b = s.bodies[0];
    const Eigen::Quaterniond q_cloud = st.q * b.model.cloud_from_principal.conjugate();
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e9), hi = -lo;
    for (const glm::vec3& p : v.surfaces[0].mesh->positions) {
      const glm::dvec4 w = v.surfaces[0].model * glm::dvec4(glm::dvec3(p), 1.0);
      const Eigen::Vector3d c = q_cloud.conjugate() * (Eigen::Vector3d(w.x, w.y, w.z) - st.c) + b.model.com_cloud;
      lo = lo.cwiseMin(c), hi = hi.cwiseMax(c);
    }
    const Eigen::Vector3d size = hi - lo;
    EXPECT_NEAR(size.x(), 0.0758, 1e-6) << "frame " << k;
    EXPECT_NEAR(size.y(), 0.1608, 1e-6) << "frame " << k;
    EXPECT_NEAR(size.z(), 0.0078, 1e-6) << "frame " << k;  // the lattice spans 0.0052
    EXPECT_NEAR((0.5 * (lo + hi)).norm(), 0, 1e-7);        // centred where the lattice is
  }
}

TEST(LessonFigures, PartsAreSurfacesInTheirOwnColours) {
  const std::string text = std::string(kPhone) + R"(
[[bodies.parts]]
shape = { type = "box", size = [0.07, 0.15, 0.0004], resolution = [4, 8, 1], mass = 0.01 }
offset = [0, 0, 0.0041]
color = [0.10, 0.30, 0.75]
)";
  const tumble::scene::Scene s = tumble::scene::load_scene_from_string(text, "phone.toml");
  const auto runs = simulate_runs(s, 2, 10);
  const tumble::viz::View v = FrameBuilder(s, runs, 10, 640, 360).build(0).views.at(0);
  ASSERT_EQ(v.surfaces.size(), 2u);
  EXPECT_EQ(glm::vec3(v.surfaces[1].color), glm::vec3(0.10f, 0.30f, 0.75f));
  EXPECT_EQ(v.surfaces[1].color.a, 1.0f);
}

TEST(LessonFigures, BodyFrameViewShowsItsOwnBodyOnly) {
  const tumble::scene::Scene s = tumble::scene::load_scene(fs::path(TUMBLE_SOURCE_DIR) / "scenes" / "poinsot.toml");
  const double fps = s.render.output.fps;
  const long frames = tumble::scene::frame_clock(s, fps).count();
  const auto runs = simulate_runs(s, frames, fps);
  const FrameBuilder fb(s, runs, fps, 960, 540);
  int seen = 0;
  for (long k = 0; k < frames; k += 5)
    for (const tumble::viz::View& v : fb.build(k).views) {
      if (v.name != "body_frame") continue;
      ++seen;
      const glm::dvec3 own = v.camera.target;  // it is aimed at its body's centre
      for (const tumble::viz::SurfaceItem& sf : v.surfaces)
        EXPECT_LT(glm::length(glm::dvec3(sf.model[3]) - own), 0.5) << "frame " << k << ": another body is drawn";
      for (const tumble::viz::TextItem& t : v.texts) EXPECT_NE(t.name, "label:stable") << "frame " << k;
    }
  EXPECT_GT(seen, 10);
}

TEST(LessonFigures, GroundGridStaysPut) {
  const char* thrown = R"(
[simulation]
duration = 1.0
fps = 10
[forces]
gravity = [0, 0, -9.81]
[[bodies]]
shape = { type = "box", size = [0.3, 0.2, 0.1] }
velocity = [0.5, 0, 4]
omega_body = [1, 5, 1]
[draw]
grid = true
)";
  const tumble::scene::Scene s = tumble::scene::load_scene_from_string(thrown, "thrown.toml");
  const auto runs = simulate_runs(s, 11, 10);
  const FrameBuilder fb(s, runs, 10, 640, 360);
  const tumble::viz::GridItem first = fb.build(0).views.at(0).grids.at(0);
  for (long k = 1; k <= 10; ++k) {
    const tumble::viz::GridItem g = fb.build(k).views.at(0).grids.at(0);
    EXPECT_EQ(g.origin, first.origin) << "frame " << k;
    EXPECT_EQ(g.spacing, first.spacing);
  }
  // Under the lowest point the body reaches (it starts lowest, then rises and falls back).
  for (const auto& states : runs[0].frames) EXPECT_LE(first.origin.z, states[0].c.z() - 0.1);
}

}  // namespace
