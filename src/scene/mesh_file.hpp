// Reads a mesh file (OBJ, STL, PLY and whatever else assimp reads) into a
// welded triangle mesh. The only file that includes assimp.
#pragma once

#include <cstddef>
#include <filesystem>
#include <vector>

#include "core/triangle_mesh.hpp"

namespace tumble::scene {

struct MeshFile {
  TriangleMesh mesh;                         ///< file units; every vertex (faces or not), welded by exact position
  std::size_t ignored_primitives = 0;        ///< lines and points, which bound no volume
};

/// Throws InputError "<path>: <what is wrong>" for unreadable, malformed or empty files.
MeshFile read_mesh_file(const std::filesystem::path& path);

}  // namespace tumble::scene
