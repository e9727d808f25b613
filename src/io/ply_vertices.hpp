// The vertex element of a PLY file (P. Turk, "The PLY Polygon File Format",
// 1994): x, y, z and an optional per-vertex `mass`, which assimp drops.
// Reads ascii, binary_little_endian and binary_big_endian; skips the elements
// before `vertex` and ignores those after it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <istream>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace tumble::io {

struct PlyVertices {
  std::vector<Eigen::Vector3d> positions;  ///< file units, in file order (not welded)
  std::vector<double> masses;              ///< kg per vertex; empty when the vertex element has no `mass`
  std::vector<std::string> warnings;       ///< "<name>:<line>: ..." for header lines that were ignored
  std::uint64_t faces = 0;                 ///< records of the `face` element (not read); 0 for a point cloud
};

/// Throws InputError: "<name>:<line>:<col>: <what was expected>" for the header,
/// "<name>: vertex <i>: ..." for the data (truncated, not finite, negative mass),
/// "<name>: ..." when the masses do not sum to a positive finite total.
PlyVertices read_ply_vertices(std::istream& in, const std::string& name);

/// The whole file checked before assimp sees it: header, every element's
/// records, and every `face` list entry a vertex index in range. Throws as above.
void check_ply_mesh(std::istream& in, const std::string& name);

/// The file at `path` (InputError naming it when it cannot be opened).
PlyVertices read_ply_vertices(const std::filesystem::path& path);

/// Whether `path` names a PLY file (extension .ply, any case).
bool is_ply_file(const std::filesystem::path& path);

}  // namespace tumble::io
