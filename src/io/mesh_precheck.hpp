// Our own structural check of a mesh file, run before assimp sees a byte of it
// (assimp hangs on a PLY header that never ends and aborts on some malformed
// faces): the formats we accept, each checked against its layout, with the
// same "<file>:<line>: ..." errors as the rest of the loader.
#pragma once

#include <string>
#include <string_view>

namespace tumble::io {

/// The formats read: OBJ (Wavefront), STL (ascii or binary), PLY, OFF.
enum class MeshFormat { obj, stl, ply, off };

/// The format named by `path`'s extension (any case); InputError for any other.
MeshFormat mesh_format(const std::string& path);

/// Throws InputError "<name>:<line>: <what was expected>" unless `bytes` is a
/// well-formed file of `format` whose faces refer to vertices it holds.
void precheck_mesh(std::string_view bytes, MeshFormat format, const std::string& name);

}  // namespace tumble::io
