// The plot view's energy levels against the exact answer: a body spun about
// e₂ has the separatrix's energy, L²/2I₂, and a fixed |L| allows at most
// L²/2I₁ (a pure e₁ spin) and at least L²/2I₃, so the levels, as ΔE/E, are
// 0, I₂/I₁ − 1 and I₂/I₃ − 1. GL-free.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "compose/frame_builder.hpp"
#include "compose/views/kinds.hpp"
#include "core/dynamics.hpp"
#include "scene/frame_clock.hpp"
#include "scene/frame_runs.hpp"
#include "scene/scene.hpp"
#include "viz/strip_chart.hpp"

namespace {

using namespace tumble;

constexpr const char* kSpinAboutE2 = R"(name = "levels"
[simulation]
method = "exact"
duration = 1.0
[[bodies]]
name = "box"
shape = { type = "box", size = [0.6, 0.36, 0.15], resolution = [12, 8, 4], mass = 1.0 }
orientation = [0.9, 0.3, -0.2, 0.1]
omega_body = [0.0, 5.0, 0.0]
)";

TEST(PlotLevels, EnergiesAFixedLAllowsForASpinAboutE2) {
  const scene::Scene s = scene::load_scene_from_string(kSpinAboutE2, "levels.toml");
  const scene::Body& b = s.bodies[0];
  const double e0 = total_energy(b.model, b.initial);
  const Eigen::Vector3d& i = b.model.inertia;
  const auto levels = compose::energy_levels(b, e0, false);
  ASSERT_EQ(levels.size(), 3u);
  EXPECT_NEAR(levels[0].value, i[1] / i[0] - 1, 1e-9) << levels[0].label;
  EXPECT_NEAR(levels[1].value, 0.0, 1e-9) << levels[1].label;
  EXPECT_NEAR(levels[2].value, i[1] / i[2] - 1, 1e-9) << levels[2].label;
  // A linear axis reads ΔE/E: each level labelled in per cent (the view's title names them).
  EXPECT_EQ(levels[0].label, viz::percent_text(i[1] / i[0] - 1));
  EXPECT_EQ(levels[1].label, "0");
  EXPECT_EQ(levels[2].label.rfind("\u2212", 0), 0u) << "below the start's energy: " << levels[2].label;
  // On a log scale: log10 |ΔE/E|, so only the levels above the start: the separatrix's 0 (to rounding)
  // has none, and L²/2I₃, a loss of 33 %, would read as a gain (|ΔE/E| drops the sign).
  const auto logs = compose::energy_levels(b, e0, true);
  ASSERT_EQ(logs.size(), 1u);
  EXPECT_NEAR(logs[0].value, std::log10(i[1] / i[0] - 1), 1e-9);
  // Named along its line by what it is and its value, not on the axis (an energy on a |ΔE/E| axis misreads).
  EXPECT_EQ(logs[0].label, "");
  EXPECT_EQ(logs[0].note, "pure e\u2081 spin, " + viz::percent_text(i[1] / i[0] - 1));
}

// methods_compare: the plot rings where explicit Euler's energy first passes
// the separatrix's, L²/2I₂ (computed here from the body's inertia and L, not
// from the plot's levels), and the scene's stop there shows the ring; RK4,
// which never gets there, has none.
TEST(PlotLevels, TheCrossingOfTheSeparatrixIsRingedAtItsTime) {
  const scene::Scene s = scene::load_scene(std::filesystem::path(TUMBLE_SOURCE_DIR) / "scenes" / "methods_compare.toml");
  const double fps = s.render.output.fps;
  const scene::FrameClock clock = scene::frame_clock(s, fps);
  const auto runs = scene::simulate_runs(s, clock.count(), fps);
  ASSERT_EQ(runs[0].label, "euler");
  const scene::Body& b = s.bodies[0];
  const double separatrix = 0.5 * b.initial.L.squaredNorm() / b.model.inertia[1];
  std::size_t j = 1;
  while (j < runs[0].frames.size() && total_energy(b.model, runs[0].frames[j][0]) < separatrix) ++j;
  ASSERT_LT(j, runs[0].frames.size()) << "Euler's energy passes the separatrix's";
  const double before = clock.time(long(j) - 1), after = clock.time(long(j));
  const compose::FrameBuilder fb(s, runs, fps, 1920, 1080);
  auto plot_of = [&](long k) {
    const viz::DrawList dl = fb.build(k);
    const auto v = std::find_if(dl.views.begin(), dl.views.end(), [](const viz::View& x) { return x.name == "plot"; });
    EXPECT_NE(v, dl.views.end());
    return v == dl.views.end() ? viz::View{} : *v;
  };
  auto rings = [](const viz::View& v) {
    return std::count_if(v.polylines.begin(), v.polylines.end(), [](const viz::PolylineItem& p) { return p.name == "point"; });
  };
  EXPECT_EQ(rings(plot_of(long(j) - 1)), 0) << "not before the crossing";
  // The stop nearest after the crossing shows it, ringed and timed.
  const auto hold = std::find_if(s.render.explain.holds.begin(), s.render.explain.holds.end(),
                                 [&](const scene::Hold& h) { return h.at >= before && h.at > 0; });
  ASSERT_NE(hold, s.render.explain.holds.end());
  long k = 0;
  while (k < clock.count() && !(clock.in_hold(k) && clock.time(k) == hold->at)) ++k;
  ASSERT_LT(k, clock.count());
  const viz::View v = plot_of(k);
  EXPECT_EQ(rings(v), 1) << "Euler's crossing only";
  const auto label = std::find_if(v.texts.begin(), v.texts.end(), [](const viz::TextItem& t) { return t.name == "point_label"; });
  ASSERT_NE(label, v.texts.end());
  const double t = std::stod(label->text.substr(label->text.find(", ") + 2));
  EXPECT_GE(t, std::floor(before * 100) / 100) << label->text;
  EXPECT_LE(t, std::ceil(after * 100) / 100) << label->text;
  EXPECT_LT(hold->at - after, 0.05) << "the stop is at the crossing, not later";
}

}  // namespace
