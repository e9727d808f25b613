// The mesh report of `tumble info`: the mesh check, how it was filled, and the
// exact tensor beside the particle cloud's.
#pragma once

#include <string>

#include "scene/scene.hpp"

namespace tumble::app {

/// Indented text lines for one mesh shape.
std::string mesh_text(const scene::MeshSource& m);

/// One JSON object (no trailing newline), indented by `indent` spaces.
std::string mesh_json(const scene::MeshSource& m, int indent);

}  // namespace tumble::app
