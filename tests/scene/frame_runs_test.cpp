// Smooth curves. Trails and polhodes come from sub-frame samples
// (dense output, never fed back), adaptive on the turning angle, the same for
// a frame range as for a full run.
#include <cmath>

#include <gtest/gtest.h>

#include "scene/frame_runs.hpp"
#include "base/error.hpp"
#include "core/dynamics.hpp"
#include "scene/scene.hpp"

namespace {

using AppRun = tumble::scene::Run;  // not gtest's Test::Run
using tumble::scene::simulate_runs;

// A fast Dzhanibekov spin (|omega| ≈ 10 rad/s at 30 fps turns 0.33 rad a frame).
std::string scene_text(double trails, const std::string& method) {
  return "[simulation]\nmethod = \"" + method + "\"\ndt = 1e-3\nduration = 2\nfps = 30\n"
         "[[bodies]]\nshape = { type = \"box\", size = [0.3, 0.1, 0.02], resolution = 4, mass = 1.0 }\n"
         "omega_body = [0.02, 10.0, 0.02]\n[draw]\ntrails = " + std::to_string(trails) + "\n";
}

AppRun simulate(double trails, const std::string& method, long frames) {
  const tumble::scene::Scene s = tumble::scene::load_scene_from_string(scene_text(trails, method), "smooth.toml");
  return simulate_runs(s, frames, s.render.output.fps).front();
}

TEST(SmoothCurves, SubFrameSamplesDoNotChangeTheFrames) {
  for (const char* method : {"rk4", "splitting", "rk45", "exact"}) {
    const AppRun plain = simulate(0, method, 61), smooth = simulate(1.0, method, 61);
    ASSERT_TRUE(plain.path.empty()) << method;  // no curves drawn: no samples kept
    ASSERT_EQ(plain.frames.size(), smooth.frames.size());
    for (std::size_t k = 0; k < plain.frames.size(); ++k) {
      const tumble::BodyState &a = plain.frames[k][0], &b = smooth.frames[k][0];
      EXPECT_EQ(a.q.coeffs(), b.q.coeffs()) << method << " frame " << k;
      EXPECT_EQ(a.L, b.L) << method << " frame " << k;
      EXPECT_EQ(a.c, b.c) << method << " frame " << k;
    }
  }
}

TEST(SmoothCurves, NoBodyTurnsMoreThanTheLimitBetweenPathSamples) {
  const tumble::scene::Scene s = tumble::scene::load_scene_from_string(scene_text(1.0, "rk4"), "smooth.toml");
  const AppRun r = simulate_runs(s, 61, 30).front();
  ASSERT_EQ(r.path_of_frame.size(), 61u);
  EXPECT_GT(r.path.size(), 61u * 6);  // 0.33 rad a frame needs ≥ 7 samples a frame at 0.05 rad
  for (std::size_t j = 1; j < r.path.size(); ++j) {
    ASSERT_LT(r.path_t[j - 1], r.path_t[j]);
    // The rotation between consecutive samples, from the quaternions: 2·acos|q_a·q_b|.
    const double turn = 2 * std::acos(std::min(1.0, std::abs(r.path[j - 1][0].q.dot(r.path[j][0].q))));
    EXPECT_LE(turn, tumble::scene::kMaxTurnPerSample * 1.01) << "between t = " << r.path_t[j - 1] << " and " << r.path_t[j];
  }
  for (std::size_t k = 0; k < r.frames.size(); ++k) EXPECT_EQ(r.path[r.path_of_frame[k]][0].q.coeffs(), r.frames[k][0].q.coeffs());
}

TEST(SmoothCurves, AFrameRangeSamplesAsTheFullRunDoes) {
  const AppRun full = simulate(1.0, "rk4", 61), part = simulate(1.0, "rk4", 31);
  ASSERT_EQ(part.path_of_frame.size(), 31u);
  const std::size_t n = part.path_end(30);
  ASSERT_EQ(full.path_end(30), n);
  for (std::size_t j = 0; j < n; ++j) {
    EXPECT_EQ(full.path_t[j], part.path_t[j]);
    EXPECT_EQ(full.path[j][0].q.coeffs(), part.path[j][0].q.coeffs());
  }
}

TEST(SmoothCurves, SubSamplesFollowTheTurnPerFrame) {
  tumble::RigidBodyModel m;
  m.mass = 1;
  m.inertia = Eigen::Vector3d(1, 2, 3);
  m.inv_inertia = m.inertia.cwiseInverse();
  tumble::BodyState s;
  s.L = Eigen::Vector3d(0, 2 * 10, 0);  // |omega| = 10 rad/s about the intermediate axis
  const std::vector<const tumble::RigidBodyModel*> models{&m};
  EXPECT_EQ(tumble::scene::sub_samples(models, {s}, 1.0 / 30), 7);   // 0.333 rad / 0.05 rad → 7
  EXPECT_EQ(tumble::scene::sub_samples(models, {s}, 1e-4), 1);       // already fine
  EXPECT_EQ(tumble::scene::sub_samples(models, {s}, 10.0), tumble::scene::kMaxSubSamples);
  s.L.setZero();
  EXPECT_EQ(tumble::scene::sub_samples(models, {s}, 1.0), 1);        // at rest: frames only
}

}  // namespace

namespace {

// Text in small views does not overlap. The poinsot scene at the
// golden size (320 × 240) has four 160 × 120 views with titles, an overlay
// line and body name labels.
TEST(SmoothCurves, AComparedMethodTakesItsOwnStep) {
  // [compare] steps: Euler at a quarter of the scene's dt, RK4 at the scene's.
  const std::string text = scene_text(0, "rk4") + "[compare]\nmethods = [\"euler\", \"rk4\"]\nsteps = { euler = 2.5e-4 }\n";
  const tumble::scene::Scene s = tumble::scene::load_scene_from_string(text, "cmp.toml");
  const std::vector<AppRun> runs = simulate_runs(s, 31, 30);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].step_label, "dt = 0.00025 s");
  EXPECT_EQ(runs[1].step_label, "dt = 0.001 s");
  // A quarter of the step: Euler's energy gain over 1 s is well under half (2.8× smaller here).
  const tumble::scene::Scene plain = tumble::scene::load_scene_from_string(
      scene_text(0, "rk4") + "[compare]\nmethods = [\"euler\", \"rk4\"]\n", "cmp.toml");
  const AppRun coarse = simulate_runs(plain, 31, 30)[0];
  const auto& m = s.bodies[0].model;
  auto drift = [&](const AppRun& r) { return tumble::total_energy(m, r.frames.back()[0]) / r.energy0[0] - 1; };
  EXPECT_GT(drift(runs[0]), 0);
  EXPECT_GT(drift(coarse), 2.0 * drift(runs[0]));
}

}  // namespace
