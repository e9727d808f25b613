// The plot view's energy levels against the exact answer: a body spun about
// e₂ has the separatrix's energy, L²/2I₂, and a fixed |L| allows at most
// L²/2I₁ (a pure e₁ spin) and at least L²/2I₃, so the levels, as ΔE/E, are
// 0, I₂/I₁ − 1 and I₂/I₃ − 1. GL-free.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "compose/views/kinds.hpp"
#include "core/dynamics.hpp"
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
  EXPECT_EQ(logs[0].label, "L\u00b2/2I\u2081");
}

}  // namespace
