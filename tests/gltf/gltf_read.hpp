// Reading an exported glTF back with tinygltf, and what a viewer computes from
// it (LINEAR keys: lerp, and slerp the short way), for the glTF tests.
#pragma once

#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <tiny_gltf.h>

namespace tumble::gltf_test {

namespace fs = std::filesystem;

inline const fs::path kScenes = fs::path(TUMBLE_SOURCE_DIR) / "scenes";

/// An accessor's floats (tightly packed, as the exporter writes them).
inline std::vector<float> floats(const tinygltf::Model& m, int accessor) {
  const tinygltf::Accessor& a = m.accessors.at(static_cast<std::size_t>(accessor));
  const tinygltf::BufferView& v = m.bufferViews.at(static_cast<std::size_t>(a.bufferView));
  const int comps = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
  EXPECT_EQ(a.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
  std::vector<float> out(a.count * static_cast<std::size_t>(comps));
  const unsigned char* p = m.buffers.at(static_cast<std::size_t>(v.buffer)).data.data() + v.byteOffset + a.byteOffset;
  std::memcpy(out.data(), p, out.size() * sizeof(float));
  return out;
}

inline tinygltf::Model load(const fs::path& path) {
  tinygltf::Model m;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  const bool ok = path.extension() == ".glb" ? loader.LoadBinaryFromFile(&m, &err, &warn, path.string())
                                             : loader.LoadASCIIFromFile(&m, &err, &warn, path.string());
  EXPECT_TRUE(ok) << err;
  return m;
}

inline int node_named(const tinygltf::Model& m, const std::string& name) {
  for (std::size_t i = 0; i < m.nodes.size(); ++i)
    if (m.nodes[i].name == name) return static_cast<int>(i);
  ADD_FAILURE() << "no node " << name;
  return -1;
}

/// One animated channel: key times and values (3 or 4 floats a key).
struct Channel {
  std::vector<float> t, v;
};

/// The channel of `node` animating `path` ("translation", "rotation").
inline Channel channel(const tinygltf::Model& m, int node, const std::string& path) {
  for (const tinygltf::Animation& anim : m.animations)
    for (const tinygltf::AnimationChannel& c : anim.channels) {
      if (c.target_node != node || c.target_path != path) continue;
      const tinygltf::AnimationSampler& s = anim.samplers.at(static_cast<std::size_t>(c.sampler));
      EXPECT_EQ(s.interpolation, "LINEAR");
      return {floats(m, s.input), floats(m, s.output)};
    }
  ADD_FAILURE() << "no " << path << " channel on node " << node;
  return {};
}

/// The key interval holding t and the fraction u of it (as the glTF spec's LINEAR).
inline std::pair<std::size_t, double> locate(const Channel& c, double t) {
  std::size_t k = 0;
  while (k + 2 < c.t.size() && c.t[k + 1] <= t) ++k;
  const double u = std::clamp((t - c.t[k]) / (c.t[k + 1] - c.t[k]), 0.0, 1.0);
  return {k, u};
}

/// A viewer's translation at time t.
inline Eigen::Vector3d lerp_at(const Channel& c, double t) {
  const auto [k, u] = locate(c, t);
  Eigen::Vector3d a, b;
  for (int i = 0; i < 3; ++i) a[i] = c.v[3 * k + i], b[i] = c.v[3 * (k + 1) + i];
  return (1 - u) * a + u * b;
}

/// A viewer's rotation at time t: slerp the short way (glTF stores x, y, z, w).
inline Eigen::Quaterniond slerp_at(const Channel& c, double t) {
  const auto [k, u] = locate(c, t);
  const float* a = &c.v[4 * k];
  const float* b = &c.v[4 * (k + 1)];
  Eigen::Quaterniond qa(a[3], a[0], a[1], a[2]), qb(b[3], b[0], b[1], b[2]);
  if (qa.dot(qb) < 0) qb.coeffs() = -qb.coeffs();
  return qa.normalized().slerp(u, qb.normalized());
}

/// The angle between two rotations, rad.
inline double angle_between(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  const Eigen::Quaterniond r = a.conjugate() * b;
  return 2 * std::atan2(r.vec().norm(), std::abs(r.w()));
}

/// glTF's axes from tumble's, as the glTF convention and the docs state them:
/// x stays, tumble's up (z) becomes +y, tumble's y becomes -z.
inline Eigen::Matrix3d y_up() {
  Eigen::Matrix3d r;
  r << 1, 0, 0, 0, 0, 1, 0, -1, 0;
  return r;
}

}  // namespace tumble::gltf_test
