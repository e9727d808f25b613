// A unit mesh on the GPU plus a per-instance buffer (model matrix, colour):
// one draw call renders every arrow shaft, every particle, etc.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "render/gl_object.hpp"
#include "render/mesh_geometry.hpp"

namespace tumble::render {

struct MeshInstance {
  glm::mat4 model;
  glm::vec4 color;
};

class InstancedMesh {
 public:
  InstancedMesh(const GlFunctions& gl, const MeshData& data);

  /// Replaces the instance list (buffer orphaned, so no GPU stall).
  void upload(const std::vector<MeshInstance>& instances);
  /// Draws the uploaded instances with the currently bound program.
  void draw() const;

 private:
  const GlFunctions* gl_;
  GlObject vao_, vertices_, indices_, instances_;
  GLsizei index_count_ = 0;
  GLsizei instance_count_ = 0;
};

}  // namespace tumble::render
