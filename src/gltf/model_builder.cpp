#include "gltf/model_builder.hpp"

#include <algorithm>
#include <cstring>
#include <limits>

namespace tumble::gltf {

void add_triangle(Geometry& g, const std::array<Eigen::Vector3d, 3>& p) {
  const Eigen::Vector3d cross = (p[1] - p[0]).cross(p[2] - p[0]);
  if (!(cross.norm() > 0)) return;
  const Eigen::Vector3f n = cross.normalized().cast<float>();
  for (const Eigen::Vector3d& v : p) {
    g.indices.push_back(static_cast<std::uint32_t>(g.positions.size() / 3));
    for (int i = 0; i < 3; ++i) {
      g.positions.push_back(static_cast<float>(v[i]));
      g.normals.push_back(n[i]);
    }
  }
}

Geometry box_geometry(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  Geometry g;
  auto corner = [&](int bits) {
    return Eigen::Vector3d(bits & 1 ? hi.x() : lo.x(), bits & 2 ? hi.y() : lo.y(), bits & 4 ? hi.z() : lo.z());
  };
  // Each face as four corners counter-clockwise seen from outside.
  static constexpr int kFaces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& f : kFaces) {
    add_triangle(g, {corner(f[0]), corner(f[1]), corner(f[2])});
    add_triangle(g, {corner(f[0]), corner(f[2]), corner(f[3])});
  }
  return g;
}

void append_mesh(Geometry& g, const TriangleMesh& m) {
  for (const auto& t : m.triangles) add_triangle(g, {m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]});
}

Geometry surface_geometry(const viz::SurfaceMesh& m) {
  Geometry g;
  for (std::size_t i = 0; i + 2 < m.positions.size(); i += 3) {
    const glm::vec3 e = glm::cross(m.positions[i + 1] - m.positions[i], m.positions[i + 2] - m.positions[i]);
    if (!(glm::length(e) > 0)) continue;  // no area, no normal
    for (std::size_t j = i; j < i + 3; ++j) {
      g.indices.push_back(static_cast<std::uint32_t>(g.positions.size() / 3));
      const glm::vec3 n = glm::normalize(m.normals[j]);  // glTF requires unit normals
      g.positions.insert(g.positions.end(), {m.positions[j].x, m.positions[j].y, m.positions[j].z});
      g.normals.insert(g.normals.end(), {n.x, n.y, n.z});
    }
  }
  return g;
}

std::vector<double> rotation(const Eigen::Quaterniond& q) { return {q.x(), q.y(), q.z(), q.w()}; }
std::vector<double> vec(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

Builder::Builder() {
  model_.asset.version = "2.0";
  model_.asset.generator = "tumble " TUMBLE_VERSION;
  model_.buffers.emplace_back();
  model_.scenes.emplace_back();
  model_.defaultScene = 0;
}

int Builder::floats(const std::vector<float>& data, int type, int comps, int target, bool bounds) {
  const int view = add_view(data.data(), data.size() * sizeof(float), target);
  tinygltf::Accessor a;
  a.bufferView = view;
  a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  a.type = type;
  a.count = data.size() / static_cast<std::size_t>(comps);
  if (bounds) {
    a.minValues.assign(comps, std::numeric_limits<double>::infinity());
    a.maxValues.assign(comps, -std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < data.size(); ++i) {
      const std::size_t c = i % static_cast<std::size_t>(comps);
      a.minValues[c] = std::min<double>(a.minValues[c], data[i]);
      a.maxValues[c] = std::max<double>(a.maxValues[c], data[i]);
    }
  }
  model_.accessors.push_back(std::move(a));
  return static_cast<int>(model_.accessors.size() - 1);
}

int Builder::material(const Eigen::Vector3d& rgb, const std::string& name) {
  tinygltf::Material m;
  m.name = name;
  m.pbrMetallicRoughness.baseColorFactor = {rgb.x(), rgb.y(), rgb.z(), 1.0};
  m.pbrMetallicRoughness.metallicFactor = 0.0;
  m.pbrMetallicRoughness.roughnessFactor = 0.6;
  model_.materials.push_back(std::move(m));
  return static_cast<int>(model_.materials.size() - 1);
}

int Builder::primitive(int mesh, const std::string& name, const Geometry& g, int material) {
  if (mesh < 0) {
    model_.meshes.emplace_back().name = name;
    mesh = static_cast<int>(model_.meshes.size() - 1);
  }
  tinygltf::Primitive p;
  p.attributes["POSITION"] = floats(g.positions, TINYGLTF_TYPE_VEC3, 3, TINYGLTF_TARGET_ARRAY_BUFFER, true);
  p.attributes["NORMAL"] = floats(g.normals, TINYGLTF_TYPE_VEC3, 3, TINYGLTF_TARGET_ARRAY_BUFFER, false);
  tinygltf::Accessor idx;
  idx.bufferView = add_view(g.indices.data(), g.indices.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  idx.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  idx.type = TINYGLTF_TYPE_SCALAR;
  idx.count = g.indices.size();
  model_.accessors.push_back(std::move(idx));
  p.indices = static_cast<int>(model_.accessors.size() - 1);
  p.material = material;
  p.mode = TINYGLTF_MODE_TRIANGLES;
  model_.meshes[static_cast<std::size_t>(mesh)].primitives.push_back(std::move(p));
  return mesh;
}

int Builder::node(const std::string& name, int parent, int mesh) {
  tinygltf::Node n;
  n.name = name;
  n.mesh = mesh;
  model_.nodes.push_back(std::move(n));
  const int id = static_cast<int>(model_.nodes.size() - 1);
  if (parent < 0) model_.scenes[0].nodes.push_back(id);
  else model_.nodes[static_cast<std::size_t>(parent)].children.push_back(id);
  return id;
}

void Builder::channel(tinygltf::Animation& anim, int node, const char* path, int times, int values) {
  tinygltf::AnimationSampler s;
  s.input = times;
  s.output = values;
  s.interpolation = "LINEAR";
  anim.samplers.push_back(s);
  tinygltf::AnimationChannel c;
  c.sampler = static_cast<int>(anim.samplers.size() - 1);
  c.target_node = node;
  c.target_path = path;
  anim.channels.push_back(c);
}

int Builder::add_view(const void* bytes, std::size_t size, int target) {
  std::vector<unsigned char>& data = model_.buffers[0].data;
  tinygltf::BufferView v;
  v.buffer = 0;
  v.byteOffset = data.size();
  v.byteLength = size;
  v.target = target;
  data.resize(data.size() + size);
  std::memcpy(data.data() + v.byteOffset, bytes, size);
  model_.bufferViews.push_back(v);
  return static_cast<int>(model_.bufferViews.size() - 1);
}

}  // namespace tumble::gltf
