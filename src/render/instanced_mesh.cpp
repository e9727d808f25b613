#include "render/instanced_mesh.hpp"

#include <cstddef>

namespace tumble::render {
namespace {

const void* mesh_offset(std::size_t bytes) { return reinterpret_cast<const void*>(bytes); }

}  // namespace

InstancedMesh::InstancedMesh(const GlFunctions& gl, const MeshData& data)
    : gl_(&gl),
      vao_(make_vertex_array(gl)),
      vertices_(make_buffer(gl)),
      indices_(make_buffer(gl)),
      instances_(make_buffer(gl)),
      index_count_(static_cast<GLsizei>(data.indices.size())) {
  gl.BindVertexArray(vao_.id());
  gl.BindBuffer(GL_ARRAY_BUFFER, vertices_.id());
  gl.BufferData(GL_ARRAY_BUFFER, data.vertices.size() * sizeof(MeshVertex),
                data.vertices.data(), GL_STATIC_DRAW);
  gl.EnableVertexAttribArray(0);
  gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(MeshVertex),
                         mesh_offset(offsetof(MeshVertex, position)));
  gl.EnableVertexAttribArray(1);
  gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(MeshVertex),
                         mesh_offset(offsetof(MeshVertex, normal)));
  gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
  gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, data.indices.size() * sizeof(std::uint32_t),
                data.indices.data(), GL_STATIC_DRAW);

  // Per-instance attributes: a mat4 takes four vec4 slots (2..5), colour 6.
  gl.BindBuffer(GL_ARRAY_BUFFER, instances_.id());
  for (GLuint col = 0; col < 4; ++col) {
    gl.EnableVertexAttribArray(2 + col);
    gl.VertexAttribPointer(2 + col, 4, GL_FLOAT, GL_FALSE, sizeof(MeshInstance),
                           mesh_offset(offsetof(MeshInstance, model) + col * sizeof(glm::vec4)));
    gl.VertexAttribDivisor(2 + col, 1);
  }
  gl.EnableVertexAttribArray(6);
  gl.VertexAttribPointer(6, 4, GL_FLOAT, GL_FALSE, sizeof(MeshInstance),
                         mesh_offset(offsetof(MeshInstance, color)));
  gl.VertexAttribDivisor(6, 1);
  gl.BindVertexArray(0);
}

void InstancedMesh::upload(const std::vector<MeshInstance>& instances) {
  gl_->BindBuffer(GL_ARRAY_BUFFER, instances_.id());
  gl_->BufferData(GL_ARRAY_BUFFER, instances.size() * sizeof(MeshInstance),
                  instances.empty() ? nullptr : instances.data(), GL_STREAM_DRAW);
  instance_count_ = static_cast<GLsizei>(instances.size());
}

void InstancedMesh::draw() const {
  if (instance_count_ == 0) return;
  gl_->BindVertexArray(vao_.id());
  gl_->DrawElementsInstanced(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr,
                             instance_count_);
}

}  // namespace tumble::render
