// A world view's own readout is its body's (not the first body's), and a view
// with `until` is drawn up to that simulated time only, the frame key it gave with it.
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "compose/frame_builder.hpp"
#include "scene/frame_runs.hpp"
#include "scene/scene.hpp"
#include "viz/draw_list.hpp"

namespace {

const char* kScene = R"(name = "two"
[simulation]
method = "exact"
duration = 1.0
fps = 30
[[bodies]]
name = "a"
shape = { type = "t_handle", handle_length = 0.8, stem_length = 0.4, thickness = 0.1, resolution = 20, mass = 1.0 }
omega_body = [0.25, 4.0, 0.7]
[[bodies]]
name = "b"
shape = { type = "t_handle", handle_length = 0.8, stem_length = 0.4, thickness = 0.1, resolution = 20, mass = 1.0 }
position = [4.0, 0.0, 0.0]
omega_body = [4.0, 0.5, 0.0]
[draw]
overlay = ["time"]
[[views]]
kind = "world"
body = "a"
viewport = [0.0, 0.0, 0.5, 1.0]
readout = ["angle", "e2_angle"]
[[views]]
kind = "world"
body = "b"
viewport = [0.5, 0.0, 0.5, 1.0]
until = 0.5
readout = ["angle", "e1_angle"]
)";

double degrees(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b)) * 180 / std::numbers::pi;
}

// The text of view v that starts with `head` (a readout's items each on a line of its own), "" when none does.
std::string text_of(const tumble::viz::View& v, const std::string& head) {
  for (const tumble::viz::TextItem& t : v.texts)
    if (t.text.rfind(head, 0) == 0) return t.text;
  return "";
}

// The number after `head` in `text`.
double value_after(const std::string& text, const std::string& head) {
  const std::size_t at = text.find(head);
  return at == std::string::npos ? -1 : std::stod(text.substr(at + head.size()));
}

TEST(ViewReadout, EachViewReadsItsOwnBodyUntilItGoes) {
  const tumble::scene::Scene s = tumble::scene::load_scene_from_string(kScene, "two.toml");
  const double fps = s.render.output.fps;
  const auto runs = tumble::scene::simulate_runs(s, 31, fps);
  const tumble::compose::FrameBuilder fb(s, runs, fps, 1280, 720);
  const std::string omega = "\u2220(\u03c9, L) = ", e1 = "\u2220(e\u2081, L) = ", e2 = "\u2220(e\u2082, L) = ";
  const long k = 9;  // t = 0.3 s: both views
  const tumble::viz::DrawList dl = fb.build(k);
  ASSERT_EQ(dl.views.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& b = runs[0].frames[static_cast<std::size_t>(k)][i];
    const auto& model = s.bodies[i].model;
    const Eigen::Vector3d w = b.q * model.inertia.cwiseInverse().cwiseProduct(b.q.conjugate() * b.L);
    const std::string line = text_of(dl.views[i], omega);
    ASSERT_FALSE(line.empty()) << "view " << i;
    EXPECT_NEAR(value_after(line, omega), degrees(w, b.L), 0.051) << line;
    const std::string& head = i == 0 ? e2 : e1;
    EXPECT_NEAR(value_after(text_of(dl.views[i], head), head), degrees(b.q * Eigen::Vector3d::Unit(i == 0 ? 1 : 0), b.L), 0.051) << line;
    EXPECT_EQ(text_of(dl.views[i], "t = "), "") << "view " << i << ": the frame's overlay is not in a view with its own readout";
  }
  // The two bodies' angles differ: each view shows its own.
  EXPECT_NE(value_after(text_of(dl.views[0], omega), omega), value_after(text_of(dl.views[1], omega), omega));
  EXPECT_EQ(fb.build(14).views.size(), 2u);  // t = 0.467 s
  EXPECT_EQ(fb.build(15).views.size(), 1u);  // t = 0.5 s: the second view is gone
  EXPECT_EQ(fb.build(30).views.size(), 1u);
}

// Two views keyed alike give their keys to one frame key; when both have
// gone (`until`) and a view without a key has taken the frame, the frame key
// goes with them: it would name what no view shows.
TEST(ViewSpan, TheFrameKeyGoesWithTheViewsItKeys) {
  const std::string scene = std::string(kScene).substr(0, std::string(kScene).find("[[views]]")) + R"(
[[views]]
kind = "world"
body = "a"
viewport = [0.0, 0.0, 0.5, 1.0]
until = 0.5
[[views]]
kind = "world"
body = "b"
viewport = [0.5, 0.0, 0.5, 1.0]
until = 0.5
[[views]]
kind = "world"
body = "a"
viewport = [0.0, 0.0, 1.0, 1.0]
appear = 0.5
key = false
)";
  const tumble::scene::Scene s = tumble::scene::load_scene_from_string(scene, "three.toml");
  const double fps = s.render.output.fps;
  const auto runs = tumble::scene::simulate_runs(s, 31, fps);
  const tumble::compose::FrameBuilder fb(s, runs, fps, 1280, 720);
  auto key_texts = [&](long k) {
    int n = 0;
    for (const tumble::viz::TextItem& t : fb.build(k).texts) n += t.name == "key";
    return n;
  };
  EXPECT_GT(key_texts(9), 0) << "t = 0.3 s: the two keyed views and their frame key";
  EXPECT_EQ(fb.build(15).views.size(), 1u);
  EXPECT_EQ(key_texts(15), 0) << "t = 0.5 s: only the view without a key";
}

}  // namespace
