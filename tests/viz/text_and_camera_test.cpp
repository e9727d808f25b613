// Text sizes in proportion to the frame, wrapping, keys that do not
// overlap themselves, the colour table as documented, and the momentum-sphere
// camera that keeps Π on the near side, turns smoothly and depends only on the past.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <fstream>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>

#include "core/dynamics.hpp"
#include "core/mass_properties.hpp"
#include "core/propagator.hpp"
#include "viz/key.hpp"
#include "viz/momentum_sphere.hpp"
#include "viz/palette.hpp"
#include "viz/scene_view.hpp"
#include "viz/sphere_camera.hpp"
#include "viz/font_metrics.hpp"
#include "viz/text_layout.hpp"

namespace tumble::viz {
namespace {

TEST(TextLayout, RoleSizesScaleWithTheFrameAndStayLegible) {
  for (TextRole r : {TextRole::title, TextRole::subtitle, TextRole::caption, TextRole::view_title, TextRole::key,
                     TextRole::label, TextRole::tick}) {
    EXPECT_FLOAT_EQ(text_px(r, 1080, 1), 2 * text_px(r, 540, 1));
    EXPECT_GE(text_px(r, 360, 1), 0.018f * 360);
  }
  EXPECT_GT(text_px(TextRole::title, 540, 1), text_px(TextRole::caption, 540, 1));
  EXPECT_GT(text_px(TextRole::caption, 540, 1), text_px(TextRole::tick, 540, 1));
}

TEST(TextLayout, TheSceneTextScaleGrowsAllButTheTitleCardAndCaptions) {
  for (TextRole r : {TextRole::view_title, TextRole::key, TextRole::label, TextRole::tick, TextRole::badge})
    EXPECT_FLOAT_EQ(text_px(r, 1080, 1.25), 1.25f * text_px(r, 1080, 1));
  for (TextRole r : {TextRole::title, TextRole::subtitle, TextRole::caption})
    EXPECT_FLOAT_EQ(text_px(r, 1080, 1.25), text_px(r, 1080, 1)) << "sized for a hall already";
}

TEST(TextLayout, WrapsAtTheWidthAndKeepsExplicitBreaks) {
  const std::string text = "Π runs along the separatrix to the opposite pole, then back.\nSecond line";
  const std::string w = wrap_text(text, 20, 250);
  EXPECT_LE(text_width(w, 20), 250.0f);
  EXPECT_GE(text_lines(w), 3);
  EXPECT_NE(w.find("\nSecond line"), std::string::npos);
  // Spaces written between words stay within a line (a legend's "   " between
  // items); a break drops them, and none lead a line.
  EXPECT_EQ(wrap_text("red = I1   green = I2", 20, 1000), "red = I1   green = I2");
  const std::string legend = wrap_text("red = smallest moment   green = intermediate   blue = largest", 20, 300);
  EXPECT_GE(text_lines(legend), 2);
  EXPECT_EQ(legend.find("\n "), std::string::npos);
  EXPECT_NE(legend.find("moment   green"), std::string::npos) << legend;
  // Widths follow DejaVu Sans drawn at the renderer's scale, where the size is
  // ascent − descent (2384 font units; an em is 2048): "H" advances 1540 units.
  EXPECT_NEAR(glyph_metrics(U'H').advance, 1540.0f / 2384.0f, 1e-4f);
  // The ink runs from H's left outline edge over its advance to i's right edge.
  const GlyphMetrics &h = glyph_metrics(U'H'), &i = glyph_metrics(U'i');
  EXPECT_NEAR(text_width("Hi", 100), 100 * (h.advance - h.ink_x0 + i.ink_x1), 1e-3f);
  EXPECT_NEAR(text_width("Hi", 200), 2 * text_width("Hi", 100), 1e-3f);
  EXPECT_NEAR(text_box({"Hi", {10, 0}, 100, {0, 0, 0, 1}}).x0, 10 + 100 * h.ink_x0, 1e-3f);
}

// A word wider than the whole line stands alone on its own line, the first
// one when it comes first: the text never starts with an empty line.
TEST(TextLayout, AWordWiderThanItsLineIsALineOfItsOwnNotAnEmptyLineFirst) {
  const float wide = text_width("Dzhanibekov", 20);
  const std::string w = wrap_text("Dzhanibekov flips", 20, 0.5f * wide);
  EXPECT_EQ(w, "Dzhanibekov\nflips");
  EXPECT_EQ(wrap_text("Dzhanibekov", 20, 0.5f * wide), "Dzhanibekov");
  EXPECT_EQ(wrap_text("a Dzhanibekov", 20, 0.5f * wide), "a\nDzhanibekov");
  EXPECT_EQ(wrap_text("one\nDzhanibekov", 20, 0.5f * wide), "one\nDzhanibekov");
}

// Near the separatrix (2E a billionth above |L|²/I₂) the polhode is still
// the body's own: two loops, each around one end of the smallest moment's
// axis (Π₁ keeps its sign), not the separatrix circles (which cross Π₁ = 0 at ±e₂).
TEST(MomentumSphere, APolhodeABillionthOffTheSeparatrixIsNotTheSeparatrix) {
  const Eigen::Vector3d I(0.0197, 0.0366, 0.0547);
  const double L = 0.3, sep = L * L / I[1];
  for (double rel : {1e-9, 1e-7}) {
    const auto curves = polhodes(I, L, sep * (1 + rel), 192);
    ASSERT_EQ(curves.size(), 2u);
    for (const auto& c : curves) {
      double lo = 1e300, hi = -1e300;
      for (const Eigen::Vector3d& p : c) lo = std::min(lo, p[0]), hi = std::max(hi, p[0]);
      EXPECT_TRUE(lo >= -1e-12 * L || hi <= 1e-12 * L) << "a curve crosses Pi1 = 0 at 2E = sep * (1 + " << rel << ")";
    }
  }
  const auto on = polhodes(I, L, sep, 192);  // exactly at the level: the separatrix itself
  ASSERT_EQ(on.size(), 2u);
  double lo = 1e300, hi = -1e300;
  for (const Eigen::Vector3d& p : on[0]) lo = std::min(lo, p[0]), hi = std::max(hi, p[0]);
  EXPECT_LT(lo, -0.1 * L);
  EXPECT_GT(hi, 0.1 * L);
}

TEST(Key, EntriesSitOnTheBackdropWithoutOverlapping) {
  View v;
  const std::vector<KeyEntry> entries = {{Swatch::line, {kAxisColors[0], kAxisColors[1], kAxisColors[2]}, "e₁ e₂ e₃"},
                                         key_entry(Meaning::L, "L, fixed in space"),
                                         key_entry(Meaning::momentum_point, "Π")};
  const Box box = add_key(v, entries, {20, 30}, 13);
  ASSERT_EQ(v.texts.size(), 3u + 3u + 2u);
  EXPECT_GT(v.texts[0].backdrop.a, 0.5f);
  for (std::size_t i = 0; i < v.texts.size(); ++i) {
    const Box b = text_box(v.texts[i]);
    EXPECT_TRUE(v.texts[i].key);
    EXPECT_GE(b.x0, box.x0);
    EXPECT_LE(b.x1, box.x1 + 0.01f);
    EXPECT_GE(b.y0, box.y0);
    EXPECT_LE(b.y1, box.y1);
    for (std::size_t j = i + 1; j < v.texts.size(); ++j) EXPECT_FALSE(b.overlaps(text_box(v.texts[j]))) << i << " " << j;
  }
  EXPECT_FLOAT_EQ(box.x0, 20.0f);  // at the corner it was given
  EXPECT_FLOAT_EQ(box.y0, 30.0f);
}

// docs/colours.md lists every meaning with the same RGB as viz::kPalette.
TEST(Palette, DocsTableMatchesTheCode) {
  std::ifstream in(std::string(TUMBLE_SOURCE_DIR) + "/docs/colours.md");
  ASSERT_TRUE(in) << "docs/colours.md";
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  for (const MeaningColor& m : kPalette) {
    const std::regex row("\\| `" + std::string(m.name) + "` \\|[^|]*\\| " + std::string(m.colour) +
                         " \\| ([0-9.]+), ([0-9.]+), ([0-9.]+) \\|");
    std::smatch got;
    ASSERT_TRUE(std::regex_search(doc, got, row)) << m.name << " (" << m.colour << ") missing from docs/colours.md";
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(std::stod(got[c + 1].str()), m.rgba[c], 1e-6) << m.name;
  }
  // One colour per meaning: no two meanings share a colour, but Π, which is L
  // seen from the body, takes L's.
  const auto same_thing = [](Meaning a, Meaning b) {
    return (a == Meaning::L && b == Meaning::momentum_point) || (a == Meaning::momentum_point && b == Meaning::L);
  };
  EXPECT_EQ(color_of(Meaning::momentum_point), color_of(Meaning::L));
  for (std::size_t i = 0; i < kPalette.size(); ++i)
    for (std::size_t j = i + 1; j < kPalette.size(); ++j)
      if (kPalette[i].meaning != Meaning::ink && kPalette[j].meaning != Meaning::ink &&
          !same_thing(kPalette[i].meaning, kPalette[j].meaning)) {
        EXPECT_GT(glm::length(glm::vec3(kPalette[i].rgba) - glm::vec3(kPalette[j].rgba)), 0.1f)
            << kPalette[i].name << " and " << kPalette[j].name;
      }
}

// Π of a body spun near its intermediate axis through two flips (closed form).
struct Flip {
  std::vector<double> t;
  std::vector<Eigen::Vector3d> pi;
  Flip() {
    const ParticleCloud cloud = make_box({3.0, 1.0, 0.4}, {6, 3, 2}, 2.0);
    const RigidBodyModel m = make_model("t", compute_mass_properties(cloud, "t"), ForceSet{});
    InitialConditions ic;
    ic.omega = {0.02, 8.0, 0.02};
    Propagator p(m, make_state(m, ic), {Method::exact, 1e-3});
    for (int i = 0; i <= 2000; ++i) {
      t.push_back(i * 0.004);
      pi.push_back(momentum_body(p.advance_to(t.back())));
    }
  }
};

TEST(SphereCamera, FollowedPiStaysOnTheNearSideAndTheCameraTurnsSmoothly) {
  const Flip f;
  SphereCameraSettings s;
  s.max_turn_deg = 180;  // unbounded: it follows Π round to the other side
  const std::vector<SpherePose> track = follow_track(f.t, f.pi, s);
  ASSERT_EQ(track.size(), f.pi.size());
  double flipped = 1;
  for (std::size_t j = 0; j < track.size(); ++j) {
    const Camera c = sphere_camera(track[j], s);
    const Eigen::Vector3d u = f.pi[j].normalized();
    flipped = std::min(flipped, u.dot(f.pi[0].normalized()));
    EXPECT_FALSE(hidden_by_ball(c.position, {u.x(), u.y(), u.z()}, kSphereBall)) << "t = " << f.t[j];
    EXPECT_NEAR(track[j].dir.norm(), 1, 1e-9);
    EXPECT_NEAR(track[j].up.dot(track[j].dir), 0, 1e-9);
    if (j == 0) continue;
    // Smooth: per 4 ms sample the view turns by less than Π does at its fastest (≈ 4 rad/s here) allows.
    EXPECT_LT(std::acos(std::min(1.0, track[j].dir.dot(track[j - 1].dir))), 0.03) << "t = " << f.t[j];
    EXPECT_LT((track[j].up - track[j - 1].up).norm(), 0.05) << "t = " << f.t[j];
  }
  EXPECT_LT(flipped, -0.9);  // Π went to the opposite pole: the camera had to follow it round
  // The fixed camera of before hides Π for part of the flip: the test can fail.
  SphereCameraSettings fixed;
  fixed.follow = false, fixed.azimuth_deg = 132, fixed.elevation_deg = 34;
  int hidden = 0;
  for (const Eigen::Vector3d& p : f.pi) {
    const Eigen::Vector3d u = p.normalized();
    hidden += hidden_by_ball(sphere_camera({}, fixed).position, {u.x(), u.y(), u.z()}, kSphereBall);
  }
  EXPECT_GT(hidden, 100);
}

// Bounded, the follow camera keeps its bearings: it turns at most 60° from
// where it started, while Π goes round to the opposite pole (and shows through the ball).
TEST(SphereCamera, FollowCameraTurnsAtMostItsBound) {
  const Flip f;
  const SphereCameraSettings s;
  ASSERT_EQ(s.max_turn_deg, 60);
  const std::vector<SpherePose> track = follow_track(f.t, f.pi, s);
  double widest = 0;
  for (const SpherePose& p : track) widest = std::max(widest, std::acos(std::min(1.0, p.dir.dot(track[0].dir))));
  EXPECT_LE(widest, 60 * std::numbers::pi / 180 + 1e-9);
  EXPECT_GT(widest, 55 * std::numbers::pi / 180);  // it did turn as far as it may
}

TEST(SphereCamera, PoseDependsOnlyOnThePast) {
  const Flip f;
  const SphereCameraSettings s;
  const std::vector<SpherePose> full = follow_track(f.t, f.pi, s);
  const std::size_t n = 777;
  const std::vector<SpherePose> part = follow_track({f.t.begin(), f.t.begin() + n}, {f.pi.begin(), f.pi.begin() + n}, s);
  EXPECT_EQ(part.back().dir, full[n - 1].dir);
  EXPECT_EQ(part.back().up, full[n - 1].up);
}

TEST(MomentumSphere, AxesLabelledWhereTheyCanBeSeen) {
  MomentumSphereInput in{Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(0.1, 1.9, 0.2), {}, 2.0};
  in.pose.dir = in.momentum.normalized();
  in.pose.up = Eigen::Vector3d(0, 0, 1);
  in.width_px = 960, in.height_px = 540, in.frame_h = 540;
  View v;
  build_momentum_sphere(v, in);
  int labels = 0;
  for (const TextItem& t : v.texts) labels += t.name.rfind("axis_label_e", 0) == 0;
  EXPECT_GE(labels, 2);  // +e2 faces the camera here, and one of ±e1 / +e3 too
  bool dot = false;
  for (const PointItem& p : v.points) dot = dot || p.name == "momentum_point";
  EXPECT_TRUE(dot);
}

}  // namespace
}  // namespace tumble::viz

namespace tumble::viz {
namespace {

// Straight down +e3 (elevation 90), a fixed sphere camera has the azimuth's
// direction at the top of the picture (azimuth 90: +e2, so the saddles ±e2
// sit at the top and bottom of the rim; azimuth 0: +e1), not the fallback up
// of a camera looking along its up (always +e2).
TEST(SphereCamera, StraightDownE3PutsTheAzimuthAtTheTop) {
  for (const double az : {90.0, 0.0}) {
    SphereCameraSettings s;
    s.follow = false;
    s.azimuth_deg = az;
    s.elevation_deg = 90;
    const Camera c = sphere_camera({}, s);
    const glm::dvec3 dir = glm::normalize(c.position - c.target);
    EXPECT_NEAR(dir.z, 1, 1e-9);
    const double a = az * std::numbers::pi / 180;
    EXPECT_NEAR(glm::dot(view_up(c), glm::dvec3(std::cos(a), std::sin(a), 0)), 1, 1e-9) << "azimuth " << az;
  }
}

// A chosen up (+e₂, 30° in front from elevation 60) is the picture's up: +e₂
// projects above the centre, −e₂ below; along the view it is ignored.
TEST(SphereCamera, AChosenUpIsThePicturesUp) {
  SphereCameraSettings s;
  s.follow = false;
  s.azimuth_deg = 90;
  s.elevation_deg = 60;
  s.up = {0, 1, 0};
  const Camera c = sphere_camera({}, s);
  const glm::dvec3 up = view_up(c);
  EXPECT_NEAR(glm::dot(up, glm::dvec3(0, 1, 0)), 1, 1e-12);  // +e₂ up (the lookAt projects it)
  s.up = {0, 0.5, std::sqrt(3.0) / 2};  // along the view: the default up
  const glm::dvec3 along = view_up(sphere_camera({}, s));
  s.up = {0, 0, 0};
  EXPECT_NEAR(glm::length(along - view_up(sphere_camera({}, s))), 0, 1e-12);
  EXPECT_LT(glm::dot(up, view_up(sphere_camera({}, s))), 0.9);  // and the chosen up did turn the picture
}

}  // namespace
}  // namespace tumble::viz
