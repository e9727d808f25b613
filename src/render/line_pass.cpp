#include "render/line_pass.hpp"

#include <algorithm>
#include <cstddef>

namespace tumble::render {

LinePass::LinePass(const GlFunctions& gl, const std::filesystem::path& shader_dir)
    : gl_(&gl),
      program_(gl, shader_dir, "line"),
      vao_(make_vertex_array(gl)),
      vbo_(make_buffer(gl)) {
  gl.BindVertexArray(vao_.id());
  gl.BindBuffer(GL_ARRAY_BUFFER, vbo_.id());
  gl.EnableVertexAttribArray(0);
  gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(LineVertex),
                         reinterpret_cast<const void*>(offsetof(LineVertex, position)));
  gl.EnableVertexAttribArray(1);
  gl.VertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(LineVertex),
                         reinterpret_cast<const void*>(offsetof(LineVertex, color)));
  gl.BindVertexArray(0);
  // Core profile only guarantees width 1; Mesa allows more in non-forward-
  // compatible contexts, so ask rather than assume.
  GLfloat range[2] = {1.0f, 1.0f};
  gl.GetFloatv(GL_ALIASED_LINE_WIDTH_RANGE, range);
  max_width_ = std::max(1.0f, range[1]);
}

void LinePass::draw(const std::vector<LineVertex>& vertices, const glm::mat4& view_proj,
                    float width_px, GLenum mode) const {
  if (vertices.size() < 2) return;
  program_.use();
  program_.set("u_view_proj", view_proj);
  gl_->LineWidth(std::clamp(width_px * scale_, 1.0f, max_width_));
  gl_->BindVertexArray(vao_.id());
  gl_->BindBuffer(GL_ARRAY_BUFFER, vbo_.id());
  gl_->BufferData(GL_ARRAY_BUFFER, vertices.size() * sizeof(LineVertex), vertices.data(),
                  GL_STREAM_DRAW);
  gl_->DrawArrays(mode, 0, static_cast<GLsizei>(vertices.size()));
}

}  // namespace tumble::render
