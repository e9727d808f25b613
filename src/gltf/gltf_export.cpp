#include "gltf/gltf_export.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <limits>
#include <sstream>

#include <tiny_gltf.h>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "viz/scene_view.hpp"

namespace tumble::gltf {

namespace {

/// Flat-shaded triangles: positions and normals per corner (3 floats each).
struct Geometry {
  std::vector<float> positions, normals;
  std::vector<std::uint32_t> indices;
};

/// Adds a triangle; one without area (a flat box's edge faces) is left out,
/// as it has no normal (glTF requires unit normals).
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

/// The box [lo, hi] (m), outward counter-clockwise faces.
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

/// A tinygltf::Model grown one buffer view at a time (one buffer, 4-byte aligned data).
class Builder {
 public:
  Builder() {
    model_.asset.version = "2.0";
    model_.asset.generator = "tumble " TUMBLE_VERSION;
    model_.buffers.emplace_back();
    model_.scenes.emplace_back();
    model_.defaultScene = 0;
  }
  tinygltf::Model& model() { return model_; }

  /// An accessor over `data` (`comps` floats per element), with min/max when asked.
  int floats(const std::vector<float>& data, int type, int comps, int target, bool bounds) {
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

  int material(const Eigen::Vector3d& rgb, const std::string& name) {
    tinygltf::Material m;
    m.name = name;
    m.pbrMetallicRoughness.baseColorFactor = {rgb.x(), rgb.y(), rgb.z(), 1.0};
    m.pbrMetallicRoughness.metallicFactor = 0.0;
    m.pbrMetallicRoughness.roughnessFactor = 0.6;
    model_.materials.push_back(std::move(m));
    return static_cast<int>(model_.materials.size() - 1);
  }

  /// Adds `g` as one primitive of mesh `mesh` (created when -1); returns the mesh.
  int primitive(int mesh, const std::string& name, const Geometry& g, int material) {
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

  /// A node (child of `parent`, or a root of the scene when -1).
  int node(const std::string& name, int parent, int mesh = -1) {
    tinygltf::Node n;
    n.name = name;
    n.mesh = mesh;
    model_.nodes.push_back(std::move(n));
    const int id = static_cast<int>(model_.nodes.size() - 1);
    if (parent < 0) model_.scenes[0].nodes.push_back(id);
    else model_.nodes[static_cast<std::size_t>(parent)].children.push_back(id);
    return id;
  }
  tinygltf::Node& at(int node) { return model_.nodes[static_cast<std::size_t>(node)]; }

 private:
  int add_view(const void* bytes, std::size_t size, int target) {
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
  tinygltf::Model model_;
};

std::vector<double> rotation(const Eigen::Quaterniond& q) { return {q.x(), q.y(), q.z(), q.w()}; }
std::vector<double> vec(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

/// The body's node tree; returns the node the keyframes move.
int add_body(Builder& b, const scene::Body& body) {
  const RigidBodyModel& m = body.model;
  const int root = b.node(body.name, -1);
  // Cloud axes about the centre of mass (the keyframes move the centre of mass).
  const int shape = b.node(body.name + "/shape", root);
  const int axes = b.node(body.name + "/principal_axes", root);
  b.at(axes).rotation = rotation(m.cloud_from_principal);
  int mesh = -1;
  for (std::size_t i = 0; i < body.meshes.size(); ++i) {
    Geometry g;
    append_mesh(g, body.meshes[i].surface);
    if (g.indices.empty()) continue;
    mesh = b.primitive(mesh, body.name, g, b.material(body.meshes[i].color, body.name + "/mesh" + std::to_string(i)));
  }
  if (mesh >= 0) {
    b.at(shape).mesh = mesh;
    b.at(shape).translation = vec(-m.com_cloud);
  } else {  // the principal box, in the principal frame
    b.at(shape).rotation = rotation(m.cloud_from_principal);
    b.at(shape).mesh = b.primitive(-1, body.name + "/box", box_geometry(m.box.center - m.box.half_extents, m.box.center + m.box.half_extents),
                                   b.material(body.color, body.name));
  }
  // The axes as the renderer draws them (viz::axis_tip), as square bars.
  const double size = std::max(m.box.half_extents.maxCoeff(), 1e-3), w = 0.03 * size;
  for (int i = 0; i < 3; ++i) {
    const glm::dvec3 tip = viz::axis_tip(m, BodyState{}, i);
    const Eigen::Vector3d hi = Eigen::Vector3d(tip.x, tip.y, tip.z) + Eigen::Vector3d::Constant(w);
    const viz::Color& c = viz::kAxisColors[i];
    const std::string name = body.name + "/axis" + std::to_string(i + 1);
    b.node(name, axes, b.primitive(-1, name, box_geometry(Eigen::Vector3d::Constant(-w), hi),
                                   b.material(Eigen::Vector3d(c.r, c.g, c.b), name)));
  }
  return root;
}

/// LINEAR translation and rotation channels of `node` from `tr` (quaternions
/// kept on one hemisphere, so interpolation takes the short way).
void add_motion(Builder& b, tinygltf::Animation& anim, int node, int time_accessor, const scene::Trajectory& tr) {
  const std::size_t n = tr.size();
  std::vector<float> pos(3 * n), rot(4 * n);
  Eigen::Vector4d prev(0, 0, 0, 1);
  for (std::size_t k = 0; k < n; ++k) {
    for (int i = 0; i < 3; ++i) pos[3 * k + i] = static_cast<float>(tr.c[3 * k + i]);
    Eigen::Vector4d q(tr.q[4 * k + 1], tr.q[4 * k + 2], tr.q[4 * k + 3], tr.q[4 * k]);  // x y z w
    if (q.dot(prev) < 0) q = -q;
    prev = q;
    for (int i = 0; i < 4; ++i) rot[4 * k + i] = static_cast<float>(q[i]);
  }
  b.at(node).translation = {pos[0], pos[1], pos[2]};
  b.at(node).rotation = {rot[0], rot[1], rot[2], rot[3]};
  const std::pair<const char*, int> outputs[] = {
      {"translation", b.floats(pos, TINYGLTF_TYPE_VEC3, 3, 0, false)},
      {"rotation", b.floats(rot, TINYGLTF_TYPE_VEC4, 4, 0, false)}};
  for (const auto& [path, output] : outputs) {
    tinygltf::AnimationSampler s;
    s.input = time_accessor;
    s.output = output;
    s.interpolation = "LINEAR";
    anim.samplers.push_back(s);
    tinygltf::AnimationChannel c;
    c.sampler = static_cast<int>(anim.samplers.size() - 1);
    c.target_node = node;
    c.target_path = path;
    anim.channels.push_back(c);
  }
}

}  // namespace

std::vector<double> keyframe_times(const scene::Scene& s, double fps) {
  return scene::sample_times(s.simulation.duration, fps > 0 ? fps : s.render.output.fps);
}

std::string gltf_bytes(const scene::Scene& s, const std::vector<scene::Trajectory>& tracks, bool binary) {
  Builder b;
  b.model().scenes[0].name = s.name;
  tinygltf::Animation anim;
  anim.name = "motion";
  int times = -1;
  for (std::size_t i = 0; i < s.bodies.size() && i < tracks.size(); ++i) {
    const int node = add_body(b, s.bodies[i]);
    if (tracks[i].size() < 2) continue;  // one keyframe is no animation: the node's pose says it
    if (times < 0) {
      const std::vector<float> t(tracks[i].t.begin(), tracks[i].t.end());
      times = b.floats(t, TINYGLTF_TYPE_SCALAR, 1, 0, true);
    }
    add_motion(b, anim, node, times, tracks[i]);
  }
  if (!anim.channels.empty()) b.model().animations.push_back(std::move(anim));
  std::ostringstream out;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&b.model(), out, !binary, binary)) throw std::runtime_error("glTF: tinygltf could not write the model");
  return std::move(out).str();
}

std::vector<scene::Trajectory> export_gltf(const scene::Scene& s, const std::filesystem::path& out, double fps,
                                           const std::string& option) {
  const std::string ext = out.extension().string();
  if (ext != ".glb" && ext != ".gltf")
    throw InputError(option + " " + out.string() + ": expected a file name ending in .glb or .gltf");
  const std::vector<double> t = keyframe_times(s, fps);
  std::vector<scene::Trajectory> tracks = scene::sample_run(s, s.simulation, t);
  io::atomic_write_file(out, gltf_bytes(s, tracks, ext == ".glb"));
  return tracks;
}

}  // namespace tumble::gltf
