// The glTF export's motion as a viewer plays it: y up, and between keys
// within the stated tolerance of an independent run of the simulation (or a
// refusal that names the fix), whatever --fps is.
#include <cmath>
#include <filesystem>

#include "base/error.hpp"
#include "gltf/gltf_export.hpp"
#include "gltf_read.hpp"
#include "scene/sampled_run.hpp"
#include "viz/scene_view.hpp"

using namespace tumble;
using namespace tumble::gltf_test;

namespace {

/// The largest angle (rad) and centre-of-mass distance (m) between what a
/// viewer plays from `file` and the simulation of `s`, sampled every `dt`
/// (every key interval's middle too), for the body `name`.
std::pair<double, double> worst_between_keys(const scene::Scene& s, const fs::path& file, const std::string& name, double dt) {
  const tinygltf::Model m = load(file);
  const int node = node_named(m, name);
  const Channel pos = channel(m, node, "translation"), rot = channel(m, node, "rotation");
  std::vector<double> times;
  for (double t = 0; t < s.simulation.duration; t += dt) times.push_back(t);
  for (std::size_t k = 0; k + 1 < rot.t.size(); ++k) times.push_back(0.5 * (double(rot.t[k]) + rot.t[k + 1]));
  std::sort(times.begin(), times.end());
  const scene::Trajectory sim = scene::sample_run(s, s.simulation, times).at(0);  // an independent run
  double angle = 0, dist = 0;
  for (std::size_t k = 0; k < sim.size(); ++k) {
    const Eigen::Quaterniond q(sim["q"][4 * k], sim["q"][4 * k + 1], sim["q"][4 * k + 2], sim["q"][4 * k + 3]);
    const Eigen::Quaterniond want(Eigen::Matrix3d(y_up() * q.toRotationMatrix()));
    angle = std::max(angle, angle_between(slerp_at(rot, sim.t[k]), want));
    const Eigen::Vector3d c = y_up() * Eigen::Vector3d(sim["c"][3 * k], sim["c"][3 * k + 1], sim["c"][3 * k + 2]);
    dist = std::max(dist, (lerp_at(pos, sim.t[k]) - c).norm());
  }
  return {angle, dist};
}

gltf::KeyOptions at_fps(double fps) {
  gltf::KeyOptions o;
  o.fps = fps;
  return o;
}

}  // namespace

TEST(GltfKeys, ThrownBodyRisesAlongY) {
  // thrown_box: thrown up at 8.8 m/s from (-0.7, 0, 0) under g = 9.81 m/s² along -z.
  const scene::Scene s = scene::load_scene(kScenes / "thrown_box.toml");
  const fs::path out = fs::path(::testing::TempDir()) / "thrown.glb";
  gltf::export_gltf(s, out);
  const Channel pos = channel(load(out), node_named(load(out), "box"), "translation");
  double top = -1e9, z = 0;
  for (std::size_t k = 0; k < pos.t.size(); ++k) {
    top = std::max(top, double(pos.v[3 * k + 1]));
    z = std::max(z, std::abs(double(pos.v[3 * k + 2])));
  }
  EXPECT_NEAR(pos.v[1], 0.0, 1e-9);
  EXPECT_GT(pos.v[4], pos.v[1]);                     // rising along +y at once
  EXPECT_NEAR(top, 8.8 * 8.8 / (2 * 9.81), 1e-3);    // to the top of its parabola, v²/2g
  EXPECT_LE(z, 1e-6);                                // tumble's y = 0 plane is glTF's z = 0
}

TEST(GltfKeys, FastSpinAtOneKeyPerSecondStaysWithinTolerance) {
  // The 8 rad/s T-handle: a key a second alone turns the wrong way between keys.
  const scene::Scene s = scene::load_scene(kScenes / "dzhanibekov.toml");
  const fs::path out = fs::path(::testing::TempDir()) / "spin.glb";
  const std::vector<scene::Trajectory> keys = gltf::export_gltf(s, out, at_fps(1));
  EXPECT_GT(keys[0].size(), 17u);  // keys were added
  const auto [angle, dist] = worst_between_keys(s, out, "t_handle", 0.01);
  EXPECT_LE(angle, gltf::kKeyTolerance);
  EXPECT_LE(dist, gltf::kKeyTolerance * 0.5);  // the T spins about its centre of mass
}

TEST(GltfKeys, ThrownTumblingBoxWithinTolerance) {
  // A parabola and a tumble: lerp of the centre of mass is checked as well as the rotation.
  const scene::Scene s = scene::load_scene(kScenes / "thrown_box.toml");
  const fs::path out = fs::path(::testing::TempDir()) / "thrown1.glb";
  gltf::export_gltf(s, out, at_fps(1));
  const auto [angle, dist] = worst_between_keys(s, out, "box", 0.005);
  EXPECT_LE(angle, gltf::kKeyTolerance);
  EXPECT_LE(dist, gltf::kKeyTolerance * viz::box_radius(s.bodies[0].model));
}

TEST(GltfKeys, LooserToleranceFewerKeys) {
  const scene::Scene s = scene::load_scene(kScenes / "dzhanibekov.toml");
  gltf::KeyOptions loose = at_fps(1);
  loose.tolerance = 0.05;
  const fs::path out = fs::path(::testing::TempDir()) / "loose.glb";
  const std::size_t n = gltf::export_gltf(s, out, loose)[0].size();
  EXPECT_LT(n, gltf::key_tracks(s, at_fps(1))[0].size());
  EXPECT_LE(worst_between_keys(s, out, "t_handle", 0.01).first, 0.05);
}

TEST(GltfKeys, TooManyKeysIsRefusedNamingTheFix) {
  const scene::Scene s = scene::load_scene(kScenes / "dzhanibekov.toml");
  gltf::KeyOptions few = at_fps(1);
  few.max_keys = 50;
  const fs::path out = fs::path(::testing::TempDir()) / "refused.glb";
  fs::remove(out);
  try {
    gltf::export_gltf(s, out, few);
    FAIL() << "no refusal";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("body 't_handle'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("--key-tolerance"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(out));
}

TEST(GltfKeys, ToleranceOutOfRangeIsRefused) {
  const scene::Scene s = scene::load_scene(kScenes / "dzhanibekov.toml");
  gltf::KeyOptions o;
  for (double bad : {0.0, 1e-9, 2.0, std::nan("")}) {
    o.tolerance = bad;
    EXPECT_THROW(gltf::key_tracks(s, o), InputError) << bad;
  }
}

// Consecutive rotation keys sit in the same hemisphere (q·q' ≥ 0): a viewer
// that interpolates the keys as stored (the glTF spec's slerp does not flip
// signs) would otherwise turn the long way round between them.
TEST(GltfKeys, RotationKeysNeverFlipBetweenQAndMinusQ) {
  for (const char* name : {"dzhanibekov.toml", "thrown_box.toml"}) {
    const scene::Scene s = scene::load_scene(kScenes / name);
    const fs::path out = fs::path(::testing::TempDir()) / "signs.glb";
    gltf::export_gltf(s, out);
    const tinygltf::Model m = load(out);
    std::size_t checked = 0;
    for (const tinygltf::Animation& anim : m.animations)
      for (const tinygltf::AnimationChannel& c : anim.channels) {
        if (c.target_path != "rotation") continue;
        const std::vector<float> v = floats(m, anim.samplers.at(static_cast<std::size_t>(c.sampler)).output);
        for (std::size_t k = 1; 4 * k + 3 < v.size(); ++k, ++checked) {
          double dot = 0;
          for (int i = 0; i < 4; ++i) dot += double(v[4 * (k - 1) + i]) * v[4 * k + i];
          ASSERT_GE(dot, 0.0) << name << ", node " << c.target_node << ": keys " << k - 1 << " and " << k << " flip sign";
        }
      }
    EXPECT_GT(checked, 20u) << name << ": too few keys to tell";
  }
}
