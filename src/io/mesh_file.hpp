// Reads a mesh file (OBJ, STL, PLY, OFF) into a welded triangle mesh: our own
// structural check first (mesh_precheck.hpp), then assimp in a guarded child
// process (isolated.hpp). The only file that includes assimp.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "core/triangle_mesh.hpp"
#include "io/isolated.hpp"
#include "io/mesh_precheck.hpp"

namespace tumble::io {

struct MeshFile {
  TriangleMesh mesh;                         ///< file units; every vertex (faces or not), welded by exact position
  std::size_t ignored_primitives = 0;        ///< lines and points, which bound no volume
};

/// Largest mesh file read, bytes (checked before reading).
inline constexpr std::size_t kMaxMeshBytes = std::size_t{1} << 30;

/// Throws InputError "<path>: <what is wrong>" for unreadable, malformed or empty
/// files, and for imports that crash or pass the default IsolationLimits (60 s, 4 GiB).
MeshFile read_mesh_file(const std::filesystem::path& path);

/// The same on a file's bytes (`name` labels messages), under `limits`.
MeshFile read_mesh_bytes(const std::string& bytes, MeshFormat format, const std::string& name,
                         const IsolationLimits& limits);

}  // namespace tumble::io
