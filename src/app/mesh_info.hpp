// The mesh report of `tumble info`: the mesh check, how it was filled, and the
// exact tensor beside the particle cloud's.
#pragma once

#include <string>

#include "io/json.hpp"
#include "scene/scene.hpp"

namespace tumble::app {

/// Indented text lines for one mesh shape.
std::string mesh_text(const scene::MeshSource& m);

/// One JSON object: the mesh check, the fill and both tensors (SI).
io::Json mesh_json(const scene::MeshSource& m);

}  // namespace tumble::app
