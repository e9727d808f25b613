// The glTF export read back with tinygltf: every shipped scene's keyframes
// equal the simulation (scene::sample_run) to 1e-6, the node tree is as
// documented and the file names the scene's colours.
#include <cmath>
#include <filesystem>
#include <map>

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include "core/error.hpp"
#include "gltf/gltf_export.hpp"
#include "scene/sampled_run.hpp"

namespace fs = std::filesystem;
using namespace tumble;

namespace {

const fs::path kScenes = fs::path(TUMBLE_SOURCE_DIR) / "scenes";

/// An accessor's floats (tightly packed, as the exporter writes them).
std::vector<float> floats(const tinygltf::Model& m, int accessor) {
  const tinygltf::Accessor& a = m.accessors.at(static_cast<std::size_t>(accessor));
  const tinygltf::BufferView& v = m.bufferViews.at(static_cast<std::size_t>(a.bufferView));
  const int comps = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
  EXPECT_EQ(a.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
  std::vector<float> out(a.count * static_cast<std::size_t>(comps));
  const unsigned char* p = m.buffers.at(static_cast<std::size_t>(v.buffer)).data.data() + v.byteOffset + a.byteOffset;
  std::memcpy(out.data(), p, out.size() * sizeof(float));
  return out;
}

tinygltf::Model load(const fs::path& path) {
  tinygltf::Model m;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  const bool ok = path.extension() == ".glb" ? loader.LoadBinaryFromFile(&m, &err, &warn, path.string())
                                             : loader.LoadASCIIFromFile(&m, &err, &warn, path.string());
  EXPECT_TRUE(ok) << err;
  return m;
}

int node_named(const tinygltf::Model& m, const std::string& name) {
  for (std::size_t i = 0; i < m.nodes.size(); ++i)
    if (m.nodes[i].name == name) return static_cast<int>(i);
  ADD_FAILURE() << "no node " << name;
  return -1;
}

/// Checks every body's keyframes in `m` against `tracks` (1e-6, relative beyond 1 m).
void expect_keyframes(const tinygltf::Model& m, const std::vector<scene::Trajectory>& tracks) {
  ASSERT_EQ(m.animations.size(), 1u);
  const tinygltf::Animation& anim = m.animations[0];
  for (const scene::Trajectory& tr : tracks) {
    const int node = node_named(m, tr.body);
    std::map<std::string, std::pair<std::vector<float>, std::vector<float>>> channels;  // path -> (t, values)
    for (const tinygltf::AnimationChannel& c : anim.channels) {
      if (c.target_node != node) continue;
      const tinygltf::AnimationSampler& s = anim.samplers.at(static_cast<std::size_t>(c.sampler));
      EXPECT_EQ(s.interpolation, "LINEAR");
      channels[c.target_path] = {floats(m, s.input), floats(m, s.output)};
    }
    ASSERT_EQ(channels.size(), 2u) << tr.body;
    const auto& [t, pos] = channels.at("translation");
    const std::vector<float>& rot = channels.at("rotation").second;
    ASSERT_EQ(t.size(), tr.size());
    double worst_c = 0, worst_q = 0;
    for (std::size_t k = 0; k < tr.size(); ++k) {
      EXPECT_NEAR(t[k], tr.t[k], 1e-6 * std::max(1.0, tr.t[k]));
      for (int i = 0; i < 3; ++i)
        worst_c = std::max(worst_c, std::abs(pos[3 * k + i] - tr.c[3 * k + i]) / std::max(1.0, std::abs(tr.c[3 * k + i])));
      // glTF stores (x, y, z, w), kept on one hemisphere: q or -q.
      double plus = 0, minus = 0;
      for (int i = 0; i < 4; ++i) {
        const double want = tr.q[4 * k + (i + 1) % 4];
        plus = std::max(plus, std::abs(rot[4 * k + i] - want));
        minus = std::max(minus, std::abs(rot[4 * k + i] + want));
      }
      worst_q = std::max(worst_q, std::min(plus, minus));
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
  // The exporter's trajectories are the simulation's: re-run independently.
  const std::vector<scene::Trajectory> tracks = scene::sample_run(s, s.simulation, gltf::keyframe_times(s));
  ASSERT_EQ(written.size(), s.bodies.size());
  ASSERT_EQ(written[0].q, tracks[0].q);
  expect_keyframes(load(out), tracks);
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
  gltf::export_gltf(s, out, 5);
  const tinygltf::Model m = load(out);
  const tinygltf::Node& body = m.nodes.at(static_cast<std::size_t>(node_named(m, "wing_nut")));
  ASSERT_EQ(body.children.size(), 2u);
  const tinygltf::Node& shape = m.nodes.at(static_cast<std::size_t>(node_named(m, "wing_nut/shape")));
  const tinygltf::Mesh& mesh = m.meshes.at(static_cast<std::size_t>(shape.mesh));
  const auto& color = m.materials.at(static_cast<std::size_t>(mesh.primitives.at(0).material)).pbrMetallicRoughness.baseColorFactor;
  EXPECT_EQ(color, (std::vector<double>{0.62, 0.64, 0.70, 1.0}));
  // The mesh's triangles, flat shaded: 3 corners each.
  EXPECT_EQ(m.accessors.at(static_cast<std::size_t>(mesh.primitives[0].attributes.at("POSITION"))).count,
            3 * s.bodies[0].meshes[0].surface.triangles.size());
  const tinygltf::Node& axes = m.nodes.at(static_cast<std::size_t>(node_named(m, "wing_nut/principal_axes")));
  EXPECT_EQ(axes.children.size(), 3u);
  for (int i = 1; i <= 3; ++i) node_named(m, "wing_nut/axis" + std::to_string(i));
  // 5 keyframes per second over 12 s: 61 of them.
  EXPECT_EQ(m.accessors.at(static_cast<std::size_t>(m.animations.at(0).samplers.at(0).input)).count, 61u);
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
