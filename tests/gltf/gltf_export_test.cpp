// The glTF export read back with tinygltf: every shipped scene's keyframes
// equal the simulation (scene::sample_run at the key times) to 1e-6 in glTF's
// y-up axes, the node tree is as documented, names survive three.js and
// Blender, and the scene's camera and light are in the file.
#include <cmath>
#include <filesystem>
#include <map>
#include <regex>
#include <set>

#include "base/error.hpp"
#include "gltf/gltf_export.hpp"
#include "gltf_read.hpp"
#include "scene/sampled_run.hpp"

using namespace tumble;
using namespace tumble::gltf_test;

namespace {

/// Checks every body's keys in `m` against `tracks` (1e-6, relative beyond 1 m), in glTF's axes.
void expect_keyframes(const tinygltf::Model& m, const std::vector<scene::Trajectory>& tracks) {
  ASSERT_EQ(m.animations.size(), 1u);
  for (const scene::Trajectory& tr : tracks) {
    const int node = node_named(m, tr.body);
    const Channel pos = channel(m, node, "translation"), rot = channel(m, node, "rotation");
    ASSERT_EQ(pos.t.size(), tr.size());
    ASSERT_EQ(rot.t, pos.t);
    double worst_c = 0, worst_q = 0;
    for (std::size_t k = 0; k < tr.size(); ++k) {
      EXPECT_NEAR(pos.t[k], tr.t[k], 1e-6 * std::max(1.0, tr.t[k]));
      const Eigen::Vector3d c = y_up() * Eigen::Vector3d(tr["c"][3 * k], tr["c"][3 * k + 1], tr["c"][3 * k + 2]);
      for (int i = 0; i < 3; ++i) worst_c = std::max(worst_c, std::abs(pos.v[3 * k + i] - c[i]) / std::max(1.0, std::abs(c[i])));
      const Eigen::Quaterniond want(Eigen::Matrix3d(y_up() * Eigen::Quaterniond(tr["q"][4 * k], tr["q"][4 * k + 1], tr["q"][4 * k + 2], tr["q"][4 * k + 3]).toRotationMatrix()));
      const float* q = &rot.v[4 * k];
      worst_q = std::max(worst_q, angle_between(Eigen::Quaterniond(q[3], q[0], q[1], q[2]).normalized(), want));
      // Consecutive keys on one hemisphere: a viewer's short-way slerp is the way the keys mean.
      if (k > 0) {
        double dot = 0;
        for (int i = 0; i < 4; ++i) dot += double(q[i]) * rot.v[4 * (k - 1) + i];
        EXPECT_GE(dot, 0) << tr.body << " key " << k;
      }
    }
    EXPECT_LE(worst_c, 1e-6) << tr.body;
    EXPECT_LE(worst_q, 1e-6) << tr.body;
  }
}

class ShippedScene : public ::testing::TestWithParam<std::string> {};

TEST_P(ShippedScene, KeyframesReadBackEqualTheSimulation) {
  const scene::Scene s = scene::load_scene(kScenes / GetParam());
  const fs::path out = fs::path(::testing::TempDir()) / (s.name + ".glb");
  const std::vector<scene::Trajectory> written = gltf::export_gltf(s, out);
  ASSERT_EQ(written.size(), s.bodies.size());
  // The exporter's trajectories are the simulation's: re-run independently at the same times.
  for (std::size_t i = 0; i < written.size(); ++i) {
    const scene::Trajectory again = scene::sample_run(s, s.simulation, written[i].t).at(i);
    ASSERT_EQ(written[i]["q"], again["q"]) << written[i].body;
    ASSERT_EQ(written[i]["c"], again["c"]) << written[i].body;
  }
  expect_keyframes(load(out), written);
}

INSTANTIATE_TEST_SUITE_P(Scenes, ShippedScene,
                         ::testing::Values("dense_box.toml", "dzhanibekov.toml", "dzhanibekov_explained.toml",
                                           "methods_compare.toml", "poinsot.toml", "reference.toml",
                                           "stable_spin.toml", "symmetric_top.toml", "tennis_racket.toml", "thrown_box.toml",
                                           "thruster.toml", "wing_nut.toml"),
                         [](const auto& info) { return info.param.substr(0, info.param.find('.')); });

TEST(GltfExport, EveryShippedSceneIsListed) {
  std::size_t n = 0;
  for (const auto& e : fs::directory_iterator(kScenes)) n += e.path().extension() == ".toml";
  EXPECT_EQ(n, 12u) << "a new scene in scenes/: add it to ShippedScene";
}

TEST(GltfExport, NodeTreeColoursAndJsonForm) {
  const scene::Scene s = scene::load_scene(kScenes / "wing_nut.toml");
  const fs::path out = fs::path(::testing::TempDir()) / "wing_nut.gltf";
  gltf::KeyOptions keys;
  keys.fps = 5;
  const std::vector<scene::Trajectory> written = gltf::export_gltf(s, out, keys);
  const tinygltf::Model m = load(out);
  const tinygltf::Node& body = m.nodes.at(static_cast<std::size_t>(node_named(m, "wing_nut")));
  ASSERT_EQ(body.children.size(), 2u);
  const tinygltf::Node& shape = m.nodes.at(static_cast<std::size_t>(node_named(m, "wing_nut_shape")));
  const tinygltf::Mesh& mesh = m.meshes.at(static_cast<std::size_t>(shape.mesh));
  const auto& color = m.materials.at(static_cast<std::size_t>(mesh.primitives.at(0).material)).pbrMetallicRoughness.baseColorFactor;
  EXPECT_EQ(color, (std::vector<double>{0.62, 0.64, 0.70, 1.0}));
  // The mesh's triangles, flat shaded: 3 corners each.
  EXPECT_EQ(m.accessors.at(static_cast<std::size_t>(mesh.primitives[0].attributes.at("POSITION"))).count,
            3 * s.bodies[0].meshes[0].surface.triangles.size());
  const tinygltf::Node& axes = m.nodes.at(static_cast<std::size_t>(node_named(m, "wing_nut_principal_axes")));
  EXPECT_EQ(axes.children.size(), 3u);
  for (int i = 1; i <= 3; ++i) node_named(m, "wing_nut_axis" + std::to_string(i));
  // 5 keyframes per second over 12 s, 61 of them, at least: --fps is a minimum.
  const Channel rot = channel(m, node_named(m, "wing_nut"), "rotation");
  EXPECT_EQ(rot.t.size(), written[0].size());
  EXPECT_GE(rot.t.size(), 61u);
  std::size_t on_grid = 0;
  for (float t : rot.t) on_grid += std::abs(t * 5 - std::round(t * 5)) < 1e-5;
  EXPECT_EQ(on_grid, 61u);
}

TEST(GltfExport, RefusesOtherExtensions) {
  const scene::Scene s = scene::load_scene(kScenes / "dzhanibekov.toml");
  try {
    gltf::export_gltf(s, fs::path(::testing::TempDir()) / "x.obj");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("expected a file name ending in .glb or .gltf"), std::string::npos);
  }
}

}  // namespace

namespace {

const char* kOddNames = R"(
name = "names"
[simulation]
duration = 1.0
[[bodies]]
name = "wing.nut"
shape = { type = "box", size = [0.2, 0.1, 0.05], mass = 1.0 }
[[bodies]]
name = "wing_nut"
shape = { type = "box", size = [0.2, 0.1, 0.05], mass = 1.0 }
position = [1, 0, 0]
[[bodies]]
name = "a_very_long_body_name_that_fills_the_sixty_four_characters_cap12"
shape = { type = "box", size = [0.2, 0.1, 0.05], mass = 1.0 }
position = [2, 0, 0]
)";

}  // namespace

TEST(GltfExport, NodeNamesSurviveThreeJsAndBlender) {
  // three.js's PropertyBinding strips [ ] . : / and Blender keeps 63 bytes and
  // renames duplicates: every name must already be what they keep, and unique.
  const scene::Scene s = scene::load_scene_from_string(kOddNames, "names.toml");
  const fs::path out = fs::path(::testing::TempDir()) / "names.gltf";
  gltf::export_gltf(s, out);
  const tinygltf::Model m = load(out);
  const std::regex kept("[A-Za-z0-9_-]{1,63}");
  std::set<std::string> seen;
  for (const tinygltf::Node& n : m.nodes) {
    EXPECT_TRUE(std::regex_match(n.name, kept)) << n.name;
    EXPECT_TRUE(seen.insert(n.name).second) << "duplicate " << n.name;
  }
  // The documented names: '.' as '_', a clash numbered, a long name cut before its suffix.
  EXPECT_EQ(m.nodes.at(static_cast<std::size_t>(node_named(m, "wing_nut"))).children.size(), 2u);
  node_named(m, "wing_nut_principal_axes");
  node_named(m, "wing_nut_2");
  node_named(m, "wing_nut_principal_axes_2");
  node_named(m, "a_very_long_body_name_that_fills_the_sixty_four_characters_cap1");
  node_named(m, "a_very_long_body_name_that_fills_the_sixty_four_character_axis1");
  // And in a shipped scene: the node to hide to hide the axes.
  const scene::Scene d = scene::load_scene(kScenes / "dzhanibekov.toml");
  gltf::export_gltf(d, out);
  node_named(load(out), "t_handle_principal_axes");
}

TEST(GltfExport, SceneCameraAndLight) {
  // One T-handle at the origin, seen by a fixed camera at (1.15, -1.7, 0.85) that looks at it: the exporter's
  // camera and light, whatever the shipped demo shows.
  const scene::Scene s = scene::load_scene_from_string(
      "[simulation]\nmethod = \"splitting\"\ndt = 1e-3\nduration = 1\nfps = 30\n"
      "[[bodies]]\nname = \"t_handle\"\n"
      "shape = { type = \"t_handle\", handle_length = 0.8, stem_length = 0.4, thickness = 0.1, resolution = 50, mass = 1.0 }\n"
      "omega_body = [0.02, 8.0, 0.02]\n"
      "[output]\nwidth = 1280\nheight = 720\n"
      "[camera]\nposition = [1.15, -1.7, 0.85]\nfov_y = 35\n",
      "camera.toml");
  const fs::path out = fs::path(::testing::TempDir()) / "camera.gltf";
  gltf::export_gltf(s, out);
  const tinygltf::Model m = load(out);
  ASSERT_EQ(m.cameras.size(), 1u);
  const tinygltf::Camera& cam = m.cameras[0];
  EXPECT_EQ(cam.type, "perspective");
  EXPECT_NEAR(cam.perspective.yfov, 35 * M_PI / 180, 1e-12);
  EXPECT_NEAR(cam.perspective.aspectRatio, 1280.0 / 720.0, 1e-12);
  const tinygltf::Node& node = m.nodes.at(static_cast<std::size_t>(node_named(m, "camera")));
  EXPECT_EQ(node.camera, 0);
  ASSERT_EQ(node.translation.size(), 3u);
  const Eigen::Vector3d eye(node.translation[0], node.translation[1], node.translation[2]);
  EXPECT_LE((eye - y_up() * Eigen::Vector3d(1.15, -1.7, 0.85)).norm(), 1e-12);
  const Eigen::Quaterniond q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
  // A glTF camera looks along its -z with +y up: at the target, with the scene's up (+z, glTF's +y) up.
  EXPECT_LE(((q * Eigen::Vector3d(0, 0, -1)) - (-eye).normalized()).norm(), 1e-12);
  EXPECT_GT((q * Eigen::Vector3d::UnitY()).y(), 0.8);
  EXPECT_NEAR((q * Eigen::Vector3d::UnitX()).y(), 0, 1e-12);  // level: no roll
  // The renderer's light, fixed to the camera (KHR_lights_punctual).
  ASSERT_EQ(m.lights.size(), 1u);
  EXPECT_EQ(m.lights[0].type, "directional");
  EXPECT_NE(std::find(m.extensionsUsed.begin(), m.extensionsUsed.end(), "KHR_lights_punctual"), m.extensionsUsed.end());
  const int light = node_named(m, "camera_light");
  EXPECT_EQ(node.children, std::vector<int>{light});
  EXPECT_EQ(m.nodes.at(static_cast<std::size_t>(light)).extensions.at("KHR_lights_punctual").Get("light").Get<int>(), 0);
}

TEST(GltfExport, GeneratedShapesAreTheirSurfaces) {
  // dzhanibekov's T-handle: handle 0.8 m along x, stem 0.4 m along y, 0.1 m bars.
  const scene::Scene s = scene::load_scene(kScenes / "dzhanibekov.toml");
  const fs::path out = fs::path(::testing::TempDir()) / "t.gltf";
  gltf::export_gltf(s, out);
  const tinygltf::Model m = load(out);
  const tinygltf::Node& shape = m.nodes.at(static_cast<std::size_t>(node_named(m, "t_handle_shape")));
  const tinygltf::Primitive& p = m.meshes.at(static_cast<std::size_t>(shape.mesh)).primitives.at(0);
  const std::vector<float> v = floats(m, p.attributes.at("POSITION"));
  // Volume enclosed (divergence theorem over the corner triples) and extent: a T, not its bounding box.
  double volume = 0;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e9), hi = -lo;
  for (std::size_t i = 0; i + 8 < v.size(); i += 9) {
    const Eigen::Vector3d a(v[i], v[i + 1], v[i + 2]), b(v[i + 3], v[i + 4], v[i + 5]), c(v[i + 6], v[i + 7], v[i + 8]);
    volume += a.dot(b.cross(c)) / 6;
    for (const Eigen::Vector3d* x : {&a, &b, &c}) lo = lo.cwiseMin(*x), hi = hi.cwiseMax(*x);
  }
  EXPECT_NEAR(volume, 0.8 * 0.1 * 0.1 + 0.4 * 0.1 * 0.1, 1e-6);
  EXPECT_LE(((hi - lo) - Eigen::Vector3d(0.8, 0.5, 0.1)).norm(), 1e-6);
}
