// A momentum sphere that hides its back (hide_far_side): nothing behind the
// ball is drawn, neither markers nor runs of curves, where by default they
// show faintly through it; the axes' names stay off the curves on the front.
#include <algorithm>

#include <gtest/gtest.h>

#include "viz/captions.hpp"
#include "viz/momentum_sphere.hpp"
#include "viz/sphere_camera.hpp"
#include "viz/sphere_figure.hpp"
#include "viz/text_layout.hpp"

namespace tumble::viz {
namespace {

const Eigen::Vector3d kI(0.00119, 0.00749, 0.00863);  // the tennis racket's moments, kg·m²

// The middle racket's Π just off +e₂ (10° towards e₃), seen with −e₂ towards the
// viewer (azimuth −60, elevation 30): +e₂ and its saddle lie behind the ball.
MomentumSphereInput behind_the_ball(bool hide) {
  const Eigen::Vector3d pi = kI.cwiseProduct(Eigen::Vector3d(0.0, 7.908, 1.21));
  MomentumSphereInput in{kI, pi, {}, pi.cwiseAbs2().cwiseQuotient(kI).sum()};
  in.camera.follow = false, in.camera.azimuth_deg = -60, in.camera.elevation_deg = 30, in.camera.distance = 14;
  in.trail = true;
  // Its path so far: from +e₂ (behind) over e₃ (in front).
  for (int k = 0; k <= 40; ++k) {
    const double a = 1.4 * k / 40;
    in.history.push_back(pi.norm() * Eigen::Vector3d(0.1 * std::sin(a), std::cos(a), std::sin(a)).normalized());
  }
  in.momentum = in.history.back();
  in.hide_far_side = hide;
  return in;
}

int markers_behind(const View& v) {
  int n = 0;
  for (const PointItem& p : v.points) n += glm::length(p.position) > 0.5 && hidden_by_ball(v.camera.position, p.position, kSphereBall);
  return n;
}

TEST(SphereFarSide, HiddenMarkersAndRunsBehindTheBallAreNotDrawn) {
  View v;
  build_momentum_sphere(v, behind_the_ball(true));
  ASSERT_TRUE(hidden_by_ball(v.camera.position, {0, 1, 0}, kSphereBall));
  EXPECT_EQ(markers_behind(v), 0);
  int saddles = 0;
  for (const PointItem& p : v.points) saddles += p.name == "saddle_+e2" || p.name == "saddle_-e2";
  EXPECT_EQ(saddles, 1);  // −e₂'s, in front
  // The curves a viewer follows reach behind the ball by their end points at most (the ball hides
  // those), and nothing is brought through it faint; the path's front run is still drawn.
  bool path = false;
  for (const PolylineItem& p : v.polylines) {
    EXPECT_FALSE(p.color.a < 0.5f && p.points.size() > 2) << "a faint run through the ball";
    if (p.name.empty()) continue;
    int behind = 0;
    for (const glm::dvec3& x : p.points) behind += hidden_by_ball(v.camera.position, x, kSphereBall);
    EXPECT_LE(behind, 2) << p.name;
    if (p.name == "polhode") path = true;
  }
  EXPECT_TRUE(path);
}

TEST(SphereFarSide, ByDefaultTheBackShowsFaintlyThroughTheBall) {
  View v;
  build_momentum_sphere(v, behind_the_ball(false));
  // Brought to the near side, faint: the +e₂ saddle and the path's far run.
  int saddles = 0;
  for (const PointItem& p : v.points) saddles += p.name == "saddle_+e2" || p.name == "saddle_-e2";
  EXPECT_EQ(saddles, 2);
  int faint = 0;
  for (const PolylineItem& p : v.polylines) faint += p.name.empty() && p.color.a < 0.5f && p.points.size() > 2;
  EXPECT_GT(faint, 0);
}

// A curve a viewer follows (named) running on past e₃'s tip, where its name goes
// first: kept clear of it where asked, over it otherwise (the old placement).
TEST(SphereFarSide, AxisNamesKeepOffTheCurvesInFront) {
  for (const bool clear : {true, false}) {
    SphereCameraSettings s;
    s.follow = false, s.azimuth_deg = -60, s.elevation_deg = 30, s.distance = 14, s.reach = kSphereReach;
    View v;
    v.camera = sphere_camera({}, s);
    add_sphere_axis_lines(v);
    PolylineItem curve{{}, {0.85f, 0.1f, 0.25f, 1}, 3, false, "polhode"};
    for (int k = 0; k <= 20; ++k) curve.points.push_back({0, 0, 1.25 + 0.3 * k / 20});
    v.polylines.push_back(curve);
    name_sphere_axes(v, 640, 360, 14, clear);
    const ViewportProjection project(v.camera, 640, 360);
    bool over = false, named = false;
    for (const TextItem& t : v.texts) {
      if (t.name != "axis_label_e3") continue;
      named = true;
      const Box b = text_box(t);
      for (const glm::dvec3& x : curve.points) {
        glm::vec2 p;
        if (project(x, p)) over = over || (p.x > b.x0 && p.x < b.x1 && p.y > b.y0 && p.y < b.y1);
      }
    }
    EXPECT_TRUE(named);
    EXPECT_EQ(over, !clear) << (clear ? "named over the curve" : "the curve no longer where the name goes first");
  }
}

// The axes' names crowded out of every place off the ball: settling may move
// them, but never onto the ball's face, where a name reads as a point on the
// sphere (with no place left, a name stays where it was put, beside its tip).
TEST(SphereFarSide, ASettledAxisNameStaysOffTheBall) {
  SphereCameraSettings s;
  s.follow = false, s.azimuth_deg = -60, s.elevation_deg = 30, s.distance = 14, s.reach = kSphereReach;
  View v;
  v.camera = sphere_camera({}, s);
  v.ball_px = ball_on_screen(v.camera, 640, 360);  // as build_momentum_sphere declares it
  add_sphere_axis_lines(v);
  name_sphere_axes(v, 640, 360, 14, true);
  const ViewportProjection project(v.camera, 640, 360);
  glm::vec2 centre, top;
  ASSERT_TRUE(project(glm::dvec3(0), centre));
  ASSERT_TRUE(project(glm::dvec3(0, 0, 1), top));
  const float ball = glm::length(top - centre);  // e₃ points nearly up the picture: about the ball's radius
  glm::vec2 tip;
  ASSERT_TRUE(project(glm::dvec3(0, 0, kAxisReach), tip));
  // Every place off the ball taken (above e₃'s tip, and either side of the ball) but e₃'s own:
  // the only clear places left near it are on the ball's face.
  std::vector<Box> taken{{0, 0, 640, tip.y - 16}, {0, 0, centre.x - ball - 2, 360}, {centre.x + ball + 2, 0, 640, 360}};
  for (const TextItem& t : v.texts)
    if (t.name == "axis_label_e3") {
      const Box b = text_box(t);
      EXPECT_GE(b.y0, tip.y - 16 - 30) << "e₃'s name first beside its tip";
      taken[0].y1 = std::min(taken[0].y1, b.y0 - 1);
    }
  settle_labels(v, 640, 360, taken);
  bool named = false;
  for (const TextItem& t : v.texts) {
    if (t.name.rfind("axis_label", 0) != 0) continue;
    const Box b = text_box(t);
    const glm::vec2 near{std::clamp(centre.x, b.x0, b.x1), std::clamp(centre.y, b.y0, b.y1)};
    if (t.name == "axis_label_e3") named = true;
    EXPECT_GE(glm::length(near - centre), 0.95f * ball) << t.text << " on the ball's face";
  }
  EXPECT_TRUE(named);
}

}  // namespace
}  // namespace tumble::viz
