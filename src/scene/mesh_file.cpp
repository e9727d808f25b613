#include "scene/mesh_file.hpp"

#include <array>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "base/error.hpp"
#include "base/input_file.hpp"

namespace tumble::scene {

namespace {

struct KeyHash {
  std::size_t operator()(const std::array<double, 3>& k) const {
    std::uint64_t h = 1469598103934665603ull;
    for (double d : k) {
      std::uint64_t b;
      std::memcpy(&b, &d, sizeof b);
      h = (h ^ b) * 1099511628211ull;
    }
    return static_cast<std::size_t>(h);
  }
};

// STL repeats each corner per facet (with the facet's normal, so assimp's
// JoinIdenticalVertices keeps them apart): weld by exact position instead.
class Welder {
 public:
  explicit Welder(TriangleMesh& m) : m_(m) {}
  int index(const Eigen::Vector3d& p) {
    const std::array<double, 3> key{p.x() + 0.0, p.y() + 0.0, p.z() + 0.0};  // -0 == +0
    auto [it, fresh] = map_.try_emplace(key, static_cast<int>(m_.vertices.size()));
    if (fresh) m_.vertices.push_back(p);
    return it->second;
  }

 private:
  TriangleMesh& m_;
  std::unordered_map<std::array<double, 3>, int, KeyHash> map_;
};

void collect(const aiScene& s, const aiNode& node, const aiMatrix4x4& parent, MeshFile& out, Welder& weld,
             const std::string& path) {
  const aiMatrix4x4 world = parent * node.mTransformation;
  for (unsigned k = 0; k < node.mNumMeshes; ++k) {
    const aiMesh& m = *s.mMeshes[node.mMeshes[k]];
    std::vector<int> ids(m.mNumVertices);
    for (unsigned v = 0; v < m.mNumVertices; ++v) {
      const aiVector3D p = world * m.mVertices[v];
      const Eigen::Vector3d q(p.x, p.y, p.z);
      if (!q.allFinite()) throw InputError(path + ": vertex " + std::to_string(v) + " is not finite");
      ids[v] = weld.index(q);
    }
    for (unsigned f = 0; f < m.mNumFaces; ++f) {
      const aiFace& face = m.mFaces[f];
      if (face.mNumIndices != 3) {
        ++out.ignored_primitives;
        continue;
      }
      std::array<int, 3> t{};
      for (int c = 0; c < 3; ++c) {
        const unsigned i = face.mIndices[c];
        if (i >= m.mNumVertices)
          throw InputError(path + ": face " + std::to_string(f) + " refers to vertex " + std::to_string(i) +
                           " of " + std::to_string(m.mNumVertices));
        t[static_cast<std::size_t>(c)] = ids[i];
      }
      out.mesh.triangles.push_back(t);
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) collect(s, *node.mChildren[c], world, out, weld, path);
}

// The mesh through the pipe: counts, then the raw vertices and triangles.
std::string encode(const MeshFile& m) {
  const std::uint64_t head[3] = {m.mesh.vertices.size(), m.mesh.triangles.size(), m.ignored_primitives};
  std::string out(reinterpret_cast<const char*>(head), sizeof head);
  for (const Eigen::Vector3d& v : m.mesh.vertices) out.append(reinterpret_cast<const char*>(v.data()), 3 * sizeof(double));
  for (const auto& t : m.mesh.triangles) out.append(reinterpret_cast<const char*>(t.data()), 3 * sizeof(int));
  return out;
}

MeshFile decode(const std::string& bytes, const std::string& name) {
  std::uint64_t head[3] = {0, 0, 0};
  if (bytes.size() >= sizeof head) std::memcpy(head, bytes.data(), sizeof head);
  const double need = sizeof head + 24.0 * static_cast<double>(head[0]) + 12.0 * static_cast<double>(head[1]);
  if (bytes.size() < sizeof head || need != static_cast<double>(bytes.size()))
    throw InputError(name + ": the guarded import returned a malformed mesh");
  MeshFile m;
  m.ignored_primitives = head[2];
  m.mesh.vertices.resize(head[0]);
  m.mesh.triangles.resize(head[1]);
  const char* p = bytes.data() + sizeof head;
  for (auto& v : m.mesh.vertices) std::memcpy(v.data(), p, 24), p += 24;
  for (auto& t : m.mesh.triangles) std::memcpy(t.data(), p, 12), p += 12;
  return m;
}

// In the guarded child: assimp on the checked bytes.
MeshFile import(const std::string& bytes, MeshFormat format, const std::string& name) {
  static constexpr const char* kHint[] = {"obj", "stl", "ply", "off"};
  Assimp::Importer importer;
  // Polygons become triangles; lines and points stay (counted, not used as faces).
  const aiScene* s = importer.ReadFileFromMemory(bytes.data(), bytes.size(),
                                                 aiProcess_Triangulate | aiProcess_ValidateDataStructure,
                                                 kHint[static_cast<int>(format)]);
  if (!s || !s->mRootNode || (s->mFlags & AI_SCENE_FLAGS_INCOMPLETE)) {
    const std::string why = importer.GetErrorString();
    throw InputError(name + ": cannot read the mesh: " + (why.empty() ? "unknown format or no geometry" : why));
  }
  MeshFile out;
  Welder weld(out.mesh);
  collect(*s, *s->mRootNode, aiMatrix4x4(), out, weld, name);
  if (out.mesh.vertices.empty()) throw InputError(name + ": the file holds no vertices");
  return out;
}

}  // namespace

MeshFile read_mesh_bytes(const std::string& bytes, MeshFormat format, const std::string& name,
                         const IsolationLimits& limits) {
  precheck_mesh(bytes, format, name);
  return decode(run_isolated([&] { return encode(import(bytes, format, name)); }, limits, name), name);
}

MeshFile read_mesh_file(const std::filesystem::path& path) {
  const MeshFormat format = mesh_format(path.string());
  std::string bytes;
  try {  // a regular file only, opened without blocking; a FIFO or device says what it is
    bytes = read_input_file(path, kMaxMeshBytes, "mesh file");
  } catch (const UnreadableFile& e) {
    throw InputError(e.what());
  } catch (const InputError& e) {
    std::error_code ec;
    if (std::filesystem::exists(std::filesystem::symlink_status(path, ec))) throw;
    throw InputError(path.string() + ": no such mesh file (paths are relative to the scene file)");
  }
  return read_mesh_bytes(bytes, format, path.string(), {});
}

}  // namespace tumble::scene
