// The frame builder's text: the overlay line keeps clear of the view title and the name labels.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>

#include <gtest/gtest.h>

#include "compose/frame_builder.hpp"
#include "scene/events.hpp"
#include "scene/frame_clock.hpp"
#include "scene/frame_runs.hpp"
#include "scene/scene.hpp"
#include "viz/draw_list.hpp"
#include "viz/text_layout.hpp"

namespace {

TEST(ViewText, OverlayClearsTheViewTitleAndTheNameLabels) {
  const tumble::scene::Scene s = tumble::scene::load_scene(std::filesystem::path(TUMBLE_SOURCE_DIR) / "scenes/poinsot.toml");
  const double fps = s.render.output.fps;
  // A frame after the body_frame view appears (t = 3.4 s): the
  // scene's title card and holds decide which frame that is.
  const tumble::scene::FrameClock clock = tumble::scene::frame_clock(s, fps);
  long k = 0;
  while (k + 1 < clock.count() && clock.time(k) < 4.0) ++k;
  const auto runs = tumble::scene::simulate_runs(s, k + 1, fps);
  const tumble::compose::FrameBuilder fb(s, runs, fps, 320, 240);
  const tumble::viz::DrawList dl = fb.build(k);
  int overlays = 0;
  for (const tumble::viz::View& v : dl.views) {
    for (const tumble::viz::TextItem& o : v.texts) {
      if (o.text.rfind("t =", 0) != 0) continue;
      ++overlays;
      // No other text (the view's title, name labels, the key beside it) on its box.
      const tumble::viz::Box ob = tumble::viz::text_box(o);
      for (const tumble::viz::TextItem& t : v.texts) {
        if (&t == &o) continue;
        EXPECT_FALSE(tumble::viz::text_box(t).overlaps(ob)) << "'" << t.text << "' on '" << o.text << "'";
      }
    }
  }
  EXPECT_EQ(overlays, 1);  // the body_frame view (the poinsot views have none)
}

// A stop at a flip reads as a deliberate hold, named: "paused at flip 1", not a bare "paused".
TEST(Badge, AHoldAtAFlipIsNamed) {
  const tumble::scene::Scene s =
      tumble::scene::load_scene(std::filesystem::path(TUMBLE_SOURCE_DIR) / "scenes/tennis_racket.toml");
  const double fps = s.render.output.fps;
  const tumble::scene::FrameClock clock = tumble::scene::frame_clock(s, fps);
  long k = 0;
  // The intro stops (t = 0 and 0.135 s) come before flip 1 (t = 0.47 s): the first hold past 0.4 s is flip 1's.
  while (k + 1 < clock.count() && !(clock.in_hold(k) && clock.time(k) > 0.4)) ++k;
  ASSERT_TRUE(clock.in_hold(k));
  long last = k;  // the hold's last frame: still named, however long the hold
  while (last + 1 < clock.count() && clock.in_hold(last + 1)) ++last;
  long after = last + 1;  // the next hold, after the flip
  while (after + 1 < clock.count() && !clock.in_hold(after)) ++after;
  ASSERT_TRUE(clock.in_hold(after));
  const auto runs = tumble::scene::simulate_runs(s, after + 1, fps);
  const tumble::compose::FrameBuilder fb(s, runs, fps, 320, 240);
  auto has = [](const tumble::viz::DrawList& dl, const std::string& text) {
    for (const tumble::viz::TextItem& t : dl.texts)
      if (t.text == text) return true;
    return false;
  };
  EXPECT_TRUE(has(fb.build(k), "paused at flip 1"));
  EXPECT_TRUE(has(fb.build(last), "paused at flip 1"));
  // The stop at the start, before anything has moved, is "paused: t = 0" (when it stands), not a bare "paused"; a hold
  // elsewhere (the one after the flip) is "paused", not "paused at flip 1" (it may still carry the
  // flip's mark, "flip 1 · paused", within its 2 s of running video).
  long start = 0;
  while (start + 1 < clock.count() && !clock.in_hold(start)) ++start;
  EXPECT_EQ(clock.time(start), 0.0);
  EXPECT_TRUE(has(fb.build(start), "paused: t = 0"));
  EXPECT_FALSE(has(fb.build(start), "paused"));
  const tumble::viz::DrawList at_after = fb.build(after);
  EXPECT_FALSE(has(at_after, "paused at flip 1"));
  EXPECT_TRUE(std::any_of(at_after.texts.begin(), at_after.texts.end(), [](const tumble::viz::TextItem& t) {
    return t.text.size() >= 6 && t.text.compare(t.text.size() - 6, 6, "paused") == 0;
  }));
}

// A stop the scene gives a reason (its `label`) says it: poinsot's stop where box 2's polhode closes.
TEST(Badge, AHoldWithALabelSaysWhyItStops) {
  const tumble::scene::Scene s = tumble::scene::load_scene(std::filesystem::path(TUMBLE_SOURCE_DIR) / "scenes/poinsot.toml");
  const auto labelled = std::find_if(s.render.explain.holds.begin(), s.render.explain.holds.end(),
                                     [](const tumble::scene::Hold& h) { return !h.label.empty(); });
  ASSERT_NE(labelled, s.render.explain.holds.end());
  const double fps = s.render.output.fps;
  const tumble::scene::FrameClock clock = tumble::scene::frame_clock(s, fps);
  long k = 0;
  while (k + 1 < clock.count() && !(clock.in_hold(k) && std::abs(clock.time(k) - labelled->at) < 1e-9)) ++k;
  ASSERT_TRUE(clock.in_hold(k));
  const auto runs = tumble::scene::simulate_runs(s, k + 1, fps);
  const tumble::compose::FrameBuilder fb(s, runs, fps, 320, 240);
  const tumble::viz::DrawList dl = fb.build(k);
  EXPECT_TRUE(std::any_of(dl.texts.begin(), dl.texts.end(),
                          [&](const tumble::viz::TextItem& t) { return t.text == "paused: " + labelled->label; }));
  // The frame before the hold runs: no reason shown.
  const tumble::viz::DrawList before = fb.build(k - 1);
  EXPECT_FALSE(std::any_of(before.texts.begin(), before.texts.end(),
                           [&](const tumble::viz::TextItem& t) { return t.text.find(labelled->label) != std::string::npos; }));
}

// Frame k's first text holding `what`, from `what` on ("" where none does).
std::string text_from(const tumble::compose::FrameBuilder& fb, long k, const std::string& what) {
  for (const tumble::viz::View& v : fb.build(k).views)
    for (const tumble::viz::TextItem& t : v.texts)
      if (const auto at = t.text.find(what); at != std::string::npos) return t.text.substr(at);
  return std::string();
}

// The first frame whose simulated time reaches `t` (the last frame if none does).
long frame_at(const tumble::scene::FrameClock& clock, double t) {
  long k = 0;
  while (k + 1 < clock.count() && clock.time(k) < t) ++k;
  return k;
}

// The first frame up to `last` that shows `what` (the first after the title card).
long first_showing(const tumble::compose::FrameBuilder& fb, long last, const std::string& what) {
  long k = 0;
  while (k < last && text_from(fb, k, what).empty()) ++k;
  return k;
}

// The demo's readout: E and |L| read the same at the start and mid-flip-1
// (a free body keeps both), |ω| and the angle between ω and L do not; the
// start's values are the exact ones, E = ½ ω·Iω, |L| = |Iω| and ∠(ω, Iω) =
// 0.097° from the scene's ω and `tumble info`'s moments. Mid-flip ω leans far
// off L: on the separatrix, half-way between ±e₂, L is 32° from e₃ and ω 60°.
TEST(Overlay, StateReadoutKeepsEAndLAndShowsOmegaChange) {
  const tumble::scene::Scene s =
      tumble::scene::load_scene(std::filesystem::path(TUMBLE_SOURCE_DIR) / "scenes/dzhanibekov.toml");
  ASSERT_TRUE(s.render.draw.overlay_items.state);
  const double fps = s.render.output.fps;
  const tumble::scene::FrameClock clock = tumble::scene::frame_clock(s, fps);
  const long k1 = frame_at(clock, 1.80);
  const auto runs = tumble::scene::simulate_runs(s, k1 + 1, fps);
  const tumble::compose::FrameBuilder fb(s, runs, fps, 1280, 720);
  // The readout's two lines: what stays fixed, what changes.
  auto readout = [&](long k, const std::string& what) { return text_from(fb, k, what); };
  const long k0 = first_showing(fb, k1, "E = ");
  ASSERT_LT(clock.time(k0), 0.05);
  EXPECT_EQ(readout(k0, "E = "), "E = 1.17 J   |L| = 0.293 kg\u00b7m\u00b2/s");
  EXPECT_EQ(readout(k0, "|\u03c9| = "), "|\u03c9| = 8.00 rad/s   \u2220(\u03c9, L) = 0.1\u00b0");
  EXPECT_EQ(readout(k1, "E = "), readout(k0, "E = "));
  const std::string flip = readout(k1, "|\u03c9| = ");
  ASSERT_NE(flip.find("\u2220(\u03c9, L) = "), std::string::npos);
  const double angle = std::stod(flip.substr(flip.find("= ", flip.find("\u2220")) + 2));
  EXPECT_GT(angle, 20.0) << flip;  // ω far off L mid-flip
  EXPECT_LT(angle, 30.0) << flip;  // and no further than on the separatrix (28°)
  EXPECT_NE(flip.substr(0, flip.find("   ")), readout(k0, "|\u03c9| = ").substr(0, flip.find("   ")));  // |ω| changes
}

// A frame key lists only what the frame draws: the small spheres' entries (saddles ±e₂) while they
// are shown, none of them once the "why" views have taken the frame (its sphere keys its own tracks).
TEST(FrameKey, ListsOnlyTheEntriesOfViewsShownNow) {
  const tumble::scene::Scene s =
      tumble::scene::load_scene(std::filesystem::path(TUMBLE_SOURCE_DIR) / "scenes/tennis_racket.toml");
  const double fps = s.render.output.fps;
  const tumble::scene::FrameClock clock = tumble::scene::frame_clock(s, fps);
  const long count = clock.count();
  const auto runs = tumble::scene::simulate_runs(s, count, fps);
  const tumble::compose::FrameBuilder fb(s, runs, fps, 960, 540);
  ASSERT_FALSE(fb.plan().frame_key.empty());
  auto has = [](const tumble::viz::DrawList& dl, const std::string& text) {
    return std::any_of(dl.texts.begin(), dl.texts.end(), [&](const tumble::viz::TextItem& t) { return t.text == text; });
  };
  long early = 0;
  while (early + 1 < count && (clock.on_title_card(early) || clock.time(early) < 0.2)) ++early;
  EXPECT_TRUE(has(fb.build(early), "saddles \u00b1e\u2082"));
  EXPECT_FALSE(has(fb.build(count - 1), "saddles \u00b1e\u2082"));
  EXPECT_FALSE(has(fb.build(count - 1), "\u03a0: L written in body axes"));
}

// tennis_racket's racket views have cameras fixed in space (follow = false):
// L stands still there, so no trail of L's tip as the body sees it is drawn
// (it turned with the racket beside a still L, unexplained).
TEST(BodyFrame, AFixedCameraDrawsNoTrailOfL) {
  const tumble::scene::Scene s =
      tumble::scene::load_scene(std::filesystem::path(TUMBLE_SOURCE_DIR) / "scenes/tennis_racket.toml");
  const double fps = s.render.output.fps;
  const long k = 700;  // past flip 1: the middle racket's L has moved far in its own axes
  const auto runs = tumble::scene::simulate_runs(s, k + 1, fps);
  const tumble::compose::FrameBuilder fb(s, runs, fps, 640, 360);
  int views = 0;
  for (const tumble::viz::View& v : fb.build(k).views) {
    if (v.name != "body_frame") continue;
    ++views;
    for (const tumble::viz::PolylineItem& p : v.polylines) EXPECT_NE(p.name, "L_trail");
  }
  EXPECT_EQ(views, 3);
}

// dzhanibekov_explained's readout of the angle between ω and L: at the start
// the exact angle of ω_body = (0.25, 4, 0.7) rad/s and L = Iω (principal
// moments from the model), and at flip 1's hold ω swung well away from L.
TEST(Overlay, AngleReadoutShowsOmegaLeavingL) {
  const tumble::scene::Scene s =
      tumble::scene::load_scene(std::filesystem::path(TUMBLE_SOURCE_DIR) / "scenes/dzhanibekov_explained.toml");
  ASSERT_TRUE(s.render.draw.overlay_items.angle);
  const double fps = s.render.output.fps;
  const tumble::scene::FrameClock clock = tumble::scene::frame_clock(s, fps);
  const long k1 = frame_at(clock, 1.29);  // flip 1 is at 1.2934 s (tumble info)
  const auto runs = tumble::scene::simulate_runs(s, k1 + 1, fps);
  const tumble::compose::FrameBuilder fb(s, runs, fps, 1280, 720);
  auto readout = [&](long k) { return text_from(fb, k, "\u2220(\u03c9, L) = "); };
  const long k0 = first_showing(fb, k1, "\u2220(\u03c9, L) = ");
  ASSERT_LT(clock.time(k0), 0.01);
  const Eigen::Vector3d w(0.25, 4.0, 0.7), L = s.bodies[0].model.inertia.cwiseProduct(w);
  const double deg = std::acos(w.dot(L) / (w.norm() * L.norm())) * 180 / std::numbers::pi;
  // and the angle of the stem e₂ (y at the start) to L, which the captions call "15° off".
  const double stem = std::acos(L.y() / L.norm()) * 180 / std::numbers::pi;
  char want[96];
  std::snprintf(want, sizeof want, "\u2220(\u03c9, L) =   %.1f\u00b0   \u2220(e\u2082, L) =   %.1f\u00b0", deg, stem);
  EXPECT_EQ(readout(k0), want);
  const std::string flip = readout(k1);
  ASSERT_FALSE(flip.empty());
  EXPECT_GT(std::stod(flip.substr(flip.find('=') + 1)), 20.0) << flip;  // 28° at the middle of the flip
}

}  // namespace

namespace {

// A world view with `body` shows that body alone, its box and its trails, and
// the readout (the first body's E, |L|, |ω|) only in the first body's view.
TEST(ViewText, AWorldViewOfOneBodyShowsItAloneWithItsTrails) {
  const tumble::scene::Scene s = tumble::scene::load_scene_from_string(R"(
name = "two"
[simulation]
duration = 1.0
fps = 30
[[bodies]]
name = "a"
shape = { type = "box", size = [0.3, 0.2, 0.1], resolution = [3, 2, 1], mass = 1.0 }
omega_body = [0.1, 5.0, 0.1]
[[bodies]]
name = "b"
shape = { type = "box", size = [0.3, 0.2, 0.1], resolution = [3, 2, 1], mass = 1.0 }
position = [3.0, 0.0, 0.0]
omega_body = [5.0, 0.1, 0.1]
[draw]
box = true
trails = 0.5
overlay = ["time", "state"]
[[views]]
kind = "world"
body = "a"
viewport = [0.0, 0.0, 0.5, 1.0]
[[views]]
kind = "world"
body = "b"
viewport = [0.5, 0.0, 0.5, 1.0]
)", "two.toml");
  ASSERT_EQ(s.bodies.size(), 2u);
  const double fps = s.render.output.fps;
  const long k = 15;  // t = 0.5 s
  const auto runs = tumble::scene::simulate_runs(s, k + 1, fps);
  const tumble::compose::FrameBuilder fb(s, runs, fps, 640, 360);
  const tumble::viz::DrawList dl = fb.build(k);
  ASSERT_EQ(dl.views.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const tumble::viz::View& v = dl.views[i];
    EXPECT_EQ(v.boxes.size(), 1u) << "view " << i << ": one body's box";
    const Eigen::Vector3d c = runs[0].frames[static_cast<std::size_t>(k)][i].c;
    int trails = 0;
    for (const tumble::viz::PolylineItem& p : v.polylines) {
      ++trails;
      for (const glm::dvec3& x : p.points)
        EXPECT_LT(glm::length(x - glm::dvec3(c.x(), c.y(), c.z())), 1.0) << "view " << i << ": its own body's trail";
    }
    EXPECT_EQ(trails, 3) << "view " << i << ": the trails of its body's three axis tips";
    int readouts = 0;
    for (const tumble::viz::TextItem& t : v.texts) readouts += t.text.rfind("t =", 0) == 0;
    EXPECT_EQ(readouts, i == 0 ? 1 : 0) << "view " << i << ": the readout is the first body's";
  }
}

}  // namespace

namespace {

// In a comparison the flips on the badge are the closed form's (the methods
// flip when they do): "exact flip 1", and "paused at exact flip 1" at its hold.
TEST(Badge, AComparisonsFlipsAreTheExactOnes) {
  const tumble::scene::Scene s =
      tumble::scene::load_scene(std::filesystem::path(TUMBLE_SOURCE_DIR) / "scenes/methods_compare.toml");
  const double fps = s.render.output.fps;
  const tumble::scene::FrameClock clock = tumble::scene::frame_clock(s, fps);
  long k = 0;  // the first hold past t = 0 is the one at flip 1 (the scene's [[holds]])
  while (k + 1 < clock.count() && !(clock.in_hold(k) && clock.time(k) > 1.0)) ++k;
  ASSERT_TRUE(clock.in_hold(k));
  long run = k;  // the first running frame after it: the flip's mark is still up
  while (run + 1 < clock.count() && clock.in_hold(run)) ++run;
  const auto runs = tumble::scene::simulate_runs(s, run + 1, fps);
  const tumble::compose::FrameBuilder fb(s, runs, fps, 960, 540);
  auto badge = [&](long f) {
    for (const tumble::viz::TextItem& t : fb.build(f).texts)
      if (t.name == "speed") return t.text;  // the status badge
    return std::string();
  };
  EXPECT_EQ(badge(k), "paused at exact flip 1");
  EXPECT_EQ(badge(run).rfind("exact flip 1", 0), 0u) << badge(run);
}

// methods_compare stops at each of the exact solution's flips (the run's events, not a time written
// near them), its "exact flip N" badge is gone 0.3 simulated s after the flip, and no
// caption says "Paused" while the animation runs.
TEST(Badge, MethodsCompareStopsAtEachExactFlipAndItsBadgeStaysNearIt) {
  const tumble::scene::Scene s =
      tumble::scene::load_scene(std::filesystem::path(TUMBLE_SOURCE_DIR) / "scenes/methods_compare.toml");
  const double fps = s.render.output.fps;
  const tumble::scene::FrameClock clock = tumble::scene::frame_clock(s, fps);
  const std::vector<double> flips = tumble::scene::body_flip_times(s, 0);
  ASSERT_EQ(flips.size(), 5u);
  const auto runs = tumble::scene::simulate_runs(s, clock.count(), fps);
  const tumble::compose::FrameBuilder fb(s, runs, fps, 480, 270);
  for (std::size_t i = 0; i < flips.size(); ++i) {
    long held = 0;
    while (held < clock.count() && !(clock.in_hold(held) && std::abs(clock.time(held) - flips[i]) < 1e-9)) ++held;
    EXPECT_LT(held, clock.count()) << "no stop at exact flip " << i + 1 << ", t = " << flips[i];
  }
  for (long k = 0; k < clock.count(); k += 2) {
    if (clock.in_hold(k)) continue;
    std::string badge;
    for (const tumble::viz::TextItem& t : fb.build(k).texts)
      if (t.name == "speed") badge = t.text;
    for (std::size_t i = 0; i < flips.size(); ++i) {
      if (std::abs(clock.time(k) - flips[i]) <= 0.3) continue;
      EXPECT_EQ(badge.find("exact flip " + std::to_string(i + 1)), std::string::npos)
          << badge << " at t = " << clock.time(k) << ", " << clock.time(k) - flips[i] << " s from the flip";
    }
  }
  for (long k = 0; k < clock.count(); ++k) {
    if (clock.in_hold(k)) continue;
    for (const auto& [c, a] : fb.captions_at(k))
      EXPECT_EQ(s.render.explain.captions[c].text.find("Paused"), std::string::npos) << "running frame " << k;
  }
}

}  // namespace
