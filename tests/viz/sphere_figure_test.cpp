// The momentum sphere as a textbook figure (GL-free): the level curves are
// smooth where they pass the saddles, arrows point the way Π moves, each axis
// is labelled at an end that can be seen from any camera, the saddles are
// marked, and what lies behind the ball shows through it faintly (the separatrix's far half not at all).
#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "viz/captions.hpp"
#include "viz/momentum_sphere.hpp"
#include "viz/sphere_camera.hpp"
#include "viz/sphere_figure.hpp"
#include "viz/text_layout.hpp"

namespace tumble::viz {
namespace {

const Eigen::Vector3d kI(0.0197, 0.0366, 0.0547);  // the T-handle's moments, kg·m²

// Π just off the separatrix near +e₂ (ω = (0.02, 8, 0.02) rad/s).
Eigen::Vector3d near_saddle() { return kI.cwiseProduct(Eigen::Vector3d(0.02, 8.0, 0.02)); }

double two_E(const Eigen::Vector3d& pi) { return pi.cwiseAbs2().cwiseQuotient(kI).sum(); }

TEST(SphereFigure, PolhodeNearTheSeparatrixIsSmoothNotJagged) {
  const Eigen::Vector3d pi = near_saddle();
  const double L = pi.norm();
  const auto curves = polhodes(kI, L, two_E(pi), 192);
  ASSERT_EQ(curves.size(), 2u);
  for (const auto& c : curves) {
    // On both surfaces, to round-off.
    for (const Eigen::Vector3d& p : c) {
      EXPECT_NEAR(p.norm() / L, 1, 1e-12);
      EXPECT_NEAR(two_E(p) / two_E(pi), 1, 1e-9);
    }
    // No chord longer than 2 % of |L| (2.5 px on a 540p sphere): 192 even steps of the
    // parameter made chords of up to 2.8 %, cutting across the bends near ±e₂.
    double longest = 0;
    for (std::size_t i = 1; i < c.size(); ++i) longest = std::max(longest, (c[i] - c[i - 1]).norm() / L);
    EXPECT_LT(longest, 0.02);
  }
}

TEST(SphereFigure, ArrowsPointTheWayPiMoves) {
  const Eigen::Vector3d pi = near_saddle();
  const double L = pi.norm();
  View v;
  v.camera = sphere_camera({}, textbook_camera(kI, pi));
  std::vector<Eigen::Vector3d> unit;
  const auto curves = polhodes(kI, L, two_E(pi), 96);
  for (const Eigen::Vector3d& p : curves[0]) unit.push_back(p / L);
  add_direction_arrows(v, unit, kI, 6, {1, 0, 1, 1}, 0.1);
  ASSERT_GE(v.arrows.size(), 2u);
  for (const ArrowItem& a : v.arrows) {
    const glm::dvec3 mid = a.origin + 0.5 * a.vector;
    const Eigen::Vector3d p(mid.x, mid.y, mid.z);
    const Eigen::Vector3d dpi = p.cross(p.cwiseQuotient(kI));  // Euler: dΠ/dt = Π × ω
    EXPECT_GT(dpi.normalized().dot(Eigen::Vector3d(a.vector.x, a.vector.y, a.vector.z).normalized()), 0.99);
  }
}

TEST(SphereFigure, EveryAxisHasALabelledEndFromAnyDirection) {
  int views = 0;
  for (int az = 0; az < 360; az += 15)
    for (int el = -80; el <= 80; el += 20) {
      SphereCameraSettings s;
      s.follow = false, s.azimuth_deg = az, s.elevation_deg = el, s.reach = kSphereReach;
      View v;
      v.camera = sphere_camera({}, s);
      add_sphere_axes(v, 640, 360, 14);
      for (int i = 1; i <= 3; ++i) {
        const std::string plus = "axis_label_e" + std::to_string(i), minus = "axis_label_-e" + std::to_string(i);
        int n = 0;
        for (const TextItem& t : v.texts) n += t.name == plus || t.name == minus;
        EXPECT_GE(n, 1) << "az " << az << " el " << el << ": e" << i << " has no label";
      }
      ++views;
    }
  EXPECT_GT(views, 100);
}

// Each label sits at its own end: its box within one and a half label heights of the end's
// tip as drawn (past the arrowhead of a + end). From the tilted view of
// dzhanibekov_explained (azimuth 90, elevation 70) the e₃ end points nearly at
// the viewer; its name used to be put at the rim beside −e₂, and −e₃'s (behind
// the ball) at the rim beside +e₂.
TEST(SphereFigure, EachLabelSitsAtItsOwnTip) {
  for (const auto& [az, el] : {std::pair{90.0, 70.0}, std::pair{20.0, 25.0}, std::pair{35.0, 30.0}, std::pair{90.0, 90.0},
                               std::pair{-60.0, 40.0}, std::pair{150.0, -30.0}}) {
    SphereCameraSettings s;
    s.follow = false, s.azimuth_deg = az, s.elevation_deg = el, s.distance = 14, s.reach = kSphereReach;
    View v;
    v.camera = sphere_camera({}, s);
    v.camera.fov_y_deg = fov_for_ball(v.camera, 1.42, 960.0 / 1080.0);
    const float label_px = 30;
    add_sphere_axes(v, 960, 1080, label_px);
    const ViewportProjection project(v.camera, 960, 1080);
    int named = 0;
    for (const TextItem& t : v.texts) {
      if (t.name.rfind("axis_label_", 0) != 0) continue;
      ++named;
      const bool minus = t.name.find("_-e") != std::string::npos;
      glm::dvec3 end(0);
      end[t.name.back() - '1'] = (minus ? -1 : 1) * kAxisReach;
      EXPECT_FALSE(hidden_by_ball(v.camera.position, end, 1.0)) << t.name << " named behind the ball";
      glm::vec2 tip;
      ASSERT_TRUE(project(end, tip));
      const Box b = text_box(t);
      const float dx = std::max({b.x0 - tip.x, 0.0f, tip.x - b.x1}), dy = std::max({b.y0 - tip.y, 0.0f, tip.y - b.y1});
      EXPECT_LE(std::hypot(dx, dy), 1.5f * label_px) << "az " << az << " el " << el << ": " << t.name << " is "
                                                       << std::hypot(dx, dy) << " px from its tip";
    }
    EXPECT_GE(named, 4) << "az " << az << " el " << el;  // six ends, at most two of them behind the ball
  }
}

// Straight down +e₃ (+e₂ at the top): +e₃ points at the viewer and is named
// beside the centre; −e₃ points straight away, wholly behind the ball, and
// gets no name (it used to be put at the top of the rim, beside +e₂).
TEST(SphereFigure, OnlyTheEndPointingAtTheViewerIsNamedEndOn) {
  for (const double el : {90.0, -90.0}) {
    SphereCameraSettings s;
    s.follow = false, s.azimuth_deg = 90, s.elevation_deg = el, s.reach = kSphereReach;
    View v;
    v.camera = sphere_camera({}, s);
    add_sphere_axes(v, 960, 1080, 30);
    const std::string toward = el > 0 ? "axis_label_e3" : "axis_label_-e3", away = el > 0 ? "axis_label_-e3" : "axis_label_e3";
    int named_toward = 0, named_away = 0, all = 0;
    for (const TextItem& t : v.texts) {
      named_toward += t.name == toward, named_away += t.name == away;
      all += t.name.rfind("axis_label_", 0) == 0;
    }
    EXPECT_EQ(named_toward, 1) << "elevation " << el;
    EXPECT_EQ(named_away, 0) << "elevation " << el;
    EXPECT_EQ(all, 5) << "elevation " << el;  // ±e₁, ±e₂ at the rim, the near e₃ end
  }
}

TEST(SphereFigure, TextbookCameraNamesTheFiveVisibleEndsAndShowsTheStartingSaddle) {
  for (const Eigen::Vector3d& omega : {Eigen::Vector3d(0.02, 8, 0.02), Eigen::Vector3d(8, 0.3, 0.3),
                                       Eigen::Vector3d(0.3, 0.3, 8), Eigen::Vector3d(-0.5, -8, 0.4)}) {
    const Eigen::Vector3d pi = kI.cwiseProduct(omega);
    View v;
    v.camera = sphere_camera({}, textbook_camera(kI, pi));
    add_sphere_axes(v, 640, 360, 14);
    int labels = 0;
    for (const TextItem& t : v.texts) labels += t.name.rfind("axis_label_", 0) == 0;
    EXPECT_EQ(labels, 5) << omega.transpose();  // the far end of the pole's axis lies behind the ball
    // Π starts in front: on the near hemisphere, not hidden by the ball.
    const Eigen::Vector3d u = pi.normalized();
    EXPECT_FALSE(hidden_by_ball(v.camera.position, {u.x(), u.y(), u.z()}, kSphereBall)) << omega.transpose();
  }
}

TEST(SphereFigure, SaddlesMarkedAndTheSeparatrixFarHalfNotDrawn) {
  const Eigen::Vector3d pi = near_saddle();
  MomentumSphereInput in{kI, pi, {}, two_E(pi)};
  in.camera = textbook_camera(kI, pi);
  View v;
  build_momentum_sphere(v, in);
  int saddles = 0;
  for (const PointItem& p : v.points) saddles += p.name == "saddle_+e2" || p.name == "saddle_-e2";
  EXPECT_EQ(saddles, 2);
  // The separatrix's far half is not drawn (seen through the ball it reads as a ring round the pole):
  // no faint separatrix-coloured run, and each drawn run reaches behind the ball by at most its last point.
  int faint = 0, runs = 0, behind = 0;
  const Color sep = color_of(Meaning::separatrix);
  for (const PolylineItem& p : v.polylines) {
    if (glm::vec3(p.color) == glm::vec3(sep) && p.color.a < sep.a) ++faint;
    if (p.name != "separatrix") continue;
    ++runs;
    for (const glm::dvec3& x : p.points) behind += hidden_by_ball(v.camera.position, x, kSphereBall);
  }
  EXPECT_GE(runs, 2);
  EXPECT_EQ(faint, 0);
  EXPECT_LE(behind, runs);
  EXPECT_GT(behind, 0);  // the textbook view does see the separatrix run round behind the ball
}

// A marker on the far hemisphere (here the −e₂ saddle, seen from 30° off +e₃
// towards +e₂ with +e₂ up) is drawn faint. Points are drawn opaque (lit balls:
// the renderer does not blend them), so faint means its colour taken most of
// the way to the ball's, not a lower alpha; the near saddle keeps its colour.
TEST(SphereFigure, AFarHemisphereMarkerIsDrawnFaint) {
  const Eigen::Vector3d pi = near_saddle();
  MomentumSphereInput in{kI, pi, {}, two_E(pi)};
  in.camera.follow = false;
  in.camera.azimuth_deg = 90, in.camera.elevation_deg = 60, in.camera.distance = 14;
  in.camera.up = Eigen::Vector3d::UnitY();
  View v;
  build_momentum_sphere(v, in);
  ASSERT_TRUE(hidden_by_ball(v.camera.position, {0, -1, 0}, kSphereBall));
  ASSERT_FALSE(hidden_by_ball(v.camera.position, {0, 1, 0}, kSphereBall));
  const glm::vec3 ring(color_of(Meaning::separatrix)), ball(kSphereBallColor);
  int seen = 0;
  for (const PointItem& p : v.points) {
    if (p.name != "saddle_-e2" && p.name != "saddle_+e2") continue;
    ++seen;
    EXPECT_EQ(p.color.a, 1.0f) << p.name;  // what the renderer draws anyway
    const float share = glm::length(glm::vec3(p.color) - ball) / glm::length(ring - ball);
    if (p.name == "saddle_-e2") EXPECT_LT(share, 0.4f);  // mostly the ball's colour
    else EXPECT_NEAR(share, 1.0f, 1e-6f);
  }
  EXPECT_EQ(seen, 2);
}

TEST(SphereFigure, EnergyEllipsoidHasItsOwnColourAndCanBeTurnedOff) {
  const Eigen::Vector3d pi = near_saddle();
  MomentumSphereInput in{kI, pi, {}, two_E(pi)};
  View on;
  build_momentum_sphere(on, in);
  ASSERT_EQ(on.surfaces.size(), 1u);
  EXPECT_EQ(glm::vec3(on.surfaces[0].color), glm::vec3(color_of(Meaning::energy_ellipsoid)));
  EXPECT_NE(glm::vec3(on.surfaces[0].color), glm::vec3(color_of(Meaning::polhode)));
  in.energy_ellipsoid = false;
  View off;
  build_momentum_sphere(off, in);
  EXPECT_TRUE(off.surfaces.empty());
  for (const KeyEntry& e : sphere_key(in)) EXPECT_EQ(e.text.find("energy ellipsoid"), std::string::npos);
}

// A lesson reveals the energy ellipsoid when its caption explains it: faded in,
// drawn at the opacity asked (none at 0), in its own colour.
TEST(SphereFigure, TheEnergyEllipsoidIsDrawnAtTheOpacityAsked) {
  const Eigen::Vector3d pi = near_saddle();
  MomentumSphereInput in{kI, pi, {}, two_E(pi)};
  in.camera = textbook_camera(kI, pi);
  EXPECT_FLOAT_EQ(in.ellipsoid_alpha, kEnergyEllipsoidAlpha);  // the veil unless asked
  in.ellipsoid_alpha = 0;
  View none;
  build_momentum_sphere(none, in);
  EXPECT_TRUE(none.surfaces.empty());
  in.ellipsoid_alpha = 0.3f;
  View half;
  build_momentum_sphere(half, in);
  ASSERT_EQ(half.surfaces.size(), 1u);
  EXPECT_FLOAT_EQ(half.surfaces[0].color.a, 0.3f);
  EXPECT_EQ(glm::vec3(half.surfaces[0].color), glm::vec3(color_of(Meaning::energy_ellipsoid)));
  in.ellipsoid_alpha = 0.7f;
  View whole;
  build_momentum_sphere(whole, in);
  ASSERT_EQ(whole.surfaces.size(), 1u);
  EXPECT_FLOAT_EQ(whole.surfaces[0].color.a, 0.7f);
}

// The key's swatch of the energy ellipsoid shows it as drawn: at its opacity,
// not at the veil's (a lesson's opaque band beside a faint swatch reads as another thing).
TEST(SphereFigure, TheKeySwatchOfTheEnergyEllipsoidHasItsOpacity) {
  const Eigen::Vector3d pi = near_saddle();
  MomentumSphereInput in{kI, pi, {}, two_E(pi)};
  in.camera = textbook_camera(kI, pi);
  for (const float alpha : {kEnergyEllipsoidAlpha, 0.9f}) {
    in.ellipsoid_alpha = alpha;
    int swatches = 0;
    for (const KeyEntry& e : sphere_key(in))
      if (e.text == "energy ellipsoid") {
        ASSERT_EQ(e.colors.size(), 1u);
        EXPECT_FLOAT_EQ(e.colors[0].a, alpha);
        EXPECT_EQ(glm::vec3(e.colors[0]), glm::vec3(color_of(Meaning::energy_ellipsoid)));
        ++swatches;
      }
    EXPECT_EQ(swatches, 1);
  }
}

// A small sphere's grey arrows are too small to see: without them the key no longer promises them.
TEST(SphereFigure, WithoutLevelArrowsNoneIsDrawnOrPromised) {
  const Eigen::Vector3d pi = near_saddle();
  MomentumSphereInput in{kI, pi, {}, two_E(pi)};
  in.camera = textbook_camera(kI, pi);
  auto grey_arrows = [](const View& v) {
    return std::count_if(v.arrows.begin(), v.arrows.end(), [](const ArrowItem& a) {
      return glm::vec3(a.color) == glm::vec3(color_of(Meaning::other_levels));
    });
  };
  auto promised = [&] {
    for (const KeyEntry& e : sphere_key(in))
      if (e.text.find("arrow") != std::string::npos) return true;
    return false;
  };
  View with;
  build_momentum_sphere(with, in);
  EXPECT_GT(grey_arrows(with), 0);
  EXPECT_TRUE(promised());
  in.level_arrows = false;
  View without;
  build_momentum_sphere(without, in);
  EXPECT_EQ(grey_arrows(without), 0);
  EXPECT_FALSE(promised());
  EXPECT_GT(without.polylines.size(), 10u);  // the grey levels themselves stay
}

// A lesson's sphere input near the saddle, seen by the textbook camera, no ellipsoid.
MomentumSphereInput lesson_input(const Eigen::Vector3d& pi) {
  MomentumSphereInput in{kI, pi, {}, two_E(pi)};
  in.camera = textbook_camera(kI, pi);
  in.energy_ellipsoid = false;
  return in;
}

// Π's dot radius in a built sphere (0 when none is drawn).
double dot_radius(const View& v) {
  for (const PointItem& p : v.points)
    if (p.name == "momentum_point") return p.radius;
  return 0.0;
}

// A lesson's sphere: Π's path so far (history) instead of its whole polhode,
// thicker curves, a larger Π dot and fewer other levels, each when asked.
TEST(SphereFigure, TrailLineScaleAndLevelsChangeOnlyWhatTheyName) {
  const Eigen::Vector3d pi = near_saddle();
  MomentumSphereInput in = lesson_input(pi);
  View plain;
  build_momentum_sphere(plain, in);
  in.trail = true, in.line_scale = 2, in.levels = 4;
  in.history = {pi, Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitZ()) * pi, Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitZ()) * pi};
  View lesson;
  build_momentum_sphere(lesson, in);
  auto named = [](const View& v, const std::string& name) {
    std::vector<const PolylineItem*> out;
    for (const PolylineItem& p : v.polylines)
      if (p.name == name) out.push_back(&p);
    return out;
  };
  // The whole polhode (closed, many points) becomes the history's three points, a hair outside the sphere.
  ASSERT_FALSE(named(plain, "polhode").empty());
  EXPECT_GT(named(plain, "polhode")[0]->points.size(), 50u);
  const auto path = named(lesson, "polhode");
  ASSERT_EQ(path.size(), 1u);
  ASSERT_EQ(path[0]->points.size(), 3u);
  EXPECT_NEAR(glm::length(path[0]->points[0]), 1.004, 1e-9);
  // The separatrix's dashes lie over the path (further out), so a path just inside it does not hide it.
  EXPECT_GT(glm::length(named(lesson, "separatrix")[0]->points[0]), glm::length(path[0]->points[0]));
  EXPECT_FLOAT_EQ(named(lesson, "separatrix")[0]->width_px, 2 * named(plain, "separatrix")[0]->width_px);
  EXPECT_DOUBLE_EQ(dot_radius(lesson), 2 * dot_radius(plain));
  // Other levels: unnamed grey curves behind the ball's front (fewer with fewer levels).
  auto grey = [](const View& v) {
    int n = 0;
    for (const PolylineItem& p : v.polylines) n += p.name.empty() && glm::vec3(p.color) == glm::vec3(color_of(Meaning::other_levels));
    return n;
  };
  EXPECT_LT(grey(lesson), grey(plain));
  EXPECT_GT(grey(lesson), 0);
}

// A hall's sphere: Π's dot dot_scale times larger, the other levels dark,
// opaque and wider; every named curve as it was.
TEST(SphereFigure, DotScaleAndDarkLevelsChangeOnlyWhatTheyName) {
  const Eigen::Vector3d pi = near_saddle();
  MomentumSphereInput in = lesson_input(pi);
  View plain;
  build_momentum_sphere(plain, in);
  in.dot_scale = 3, in.dark_levels = true;
  View bold;
  build_momentum_sphere(bold, in);
  EXPECT_DOUBLE_EQ(dot_radius(bold), 3 * dot_radius(plain));
  ASSERT_EQ(bold.polylines.size(), plain.polylines.size());
  int levels = 0;
  for (std::size_t i = 0; i < plain.polylines.size(); ++i) {
    const PolylineItem &a = plain.polylines[i], &b = bold.polylines[i];
    if (a.name.empty() && glm::vec3(a.color) == glm::vec3(color_of(Meaning::other_levels))) {
      ++levels;
      EXPECT_LT(b.color.r, 0.7f * a.color.r);
      EXPECT_EQ(b.color.a, 1.0f);
      EXPECT_LT(a.color.a, 0.6f);
      EXPECT_GT(b.width_px, 1.5f * a.width_px);
    } else {
      EXPECT_EQ(b.color, a.color) << a.name;
      EXPECT_EQ(b.width_px, a.width_px) << a.name;
    }
  }
  EXPECT_GT(levels, 8);
}

}  // namespace
}  // namespace tumble::viz
