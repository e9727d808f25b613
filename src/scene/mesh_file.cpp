#include "scene/mesh_file.hpp"

#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "core/error.hpp"

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
             const std::filesystem::path& path) {
  const aiMatrix4x4 world = parent * node.mTransformation;
  for (unsigned k = 0; k < node.mNumMeshes; ++k) {
    const aiMesh& m = *s.mMeshes[node.mMeshes[k]];
    std::vector<int> ids(m.mNumVertices);
    for (unsigned v = 0; v < m.mNumVertices; ++v) {
      const aiVector3D p = world * m.mVertices[v];
      const Eigen::Vector3d q(p.x, p.y, p.z);
      if (!q.allFinite()) throw InputError(path.string() + ": vertex " + std::to_string(v) + " is not finite");
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
          throw InputError(path.string() + ": face " + std::to_string(f) + " refers to vertex " + std::to_string(i) +
                           " of " + std::to_string(m.mNumVertices));
        t[static_cast<std::size_t>(c)] = ids[i];
      }
      out.mesh.triangles.push_back(t);
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) collect(s, *node.mChildren[c], world, out, weld, path);
}

// OFF and PLY headers declare their element counts, and assimp reserves (and
// walks) that many before noticing the file is short: a forged count of 3e11
// costs a minute. Refuse counts that the file's size cannot hold.
void check_declared_counts(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  std::error_code ec;
  const double size = static_cast<double>(std::filesystem::file_size(path, ec));
  std::istringstream lines(head);
  std::string line;
  double declared = 0;  // bytes the declared elements need at least
  if (head.rfind("OFF", 0) == 0) {
    std::getline(lines, line);
    while (std::getline(lines, line) && (line.empty() || line[0] == '#')) {
    }
    std::istringstream counts(line);
    double nv = 0, nf = 0;
    counts >> nv >> nf;
    declared = 6 * nv + 8 * nf;  // "0 0 0\n", "3 0 1 2\n"
  } else if (head.rfind("ply", 0) == 0) {
    while (std::getline(lines, line) && line.rfind("end_header", 0) != 0) {
      std::istringstream words(line);
      std::string kw, name;
      double n = 0;
      if (words >> kw >> name >> n && kw == "element") declared += n;  // a byte each, at least
    }
  }
  if (declared > size)
    throw InputError(path.string() + ": the header declares more elements than a file of " +
                     std::to_string(static_cast<long long>(size)) + " bytes can hold (truncated or forged)");
}

}  // namespace

MeshFile read_mesh_file(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(path.string() + ": no such mesh file (paths are relative to the scene file)");
  check_declared_counts(path);
  Assimp::Importer importer;
  // Polygons become triangles; lines and points stay (counted, not used as faces).
  const aiScene* s = importer.ReadFile(path.string(), aiProcess_Triangulate | aiProcess_ValidateDataStructure);
  if (!s || !s->mRootNode || (s->mFlags & AI_SCENE_FLAGS_INCOMPLETE)) {
    const std::string why = importer.GetErrorString();
    throw InputError(path.string() + ": cannot read the mesh: " + (why.empty() ? "unknown format or no geometry" : why));
  }
  MeshFile out;
  Welder weld(out.mesh);
  collect(*s, *s->mRootNode, aiMatrix4x4(), out, weld, path);
  if (out.mesh.vertices.empty()) throw InputError(path.string() + ": the file holds no vertices");
  return out;
}

}  // namespace tumble::scene
