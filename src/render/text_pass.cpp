#include "render/text_pass.hpp"

#include <cstddef>

namespace tumble::render {
namespace {

const void* text_offset(std::size_t bytes) { return reinterpret_cast<const void*>(bytes); }

}  // namespace

TextPass::TextPass(const GlFunctions& gl, const std::filesystem::path& shader_dir,
                   const FontAtlas& atlas)
    : gl_(&gl),
      program_(gl, shader_dir, "text"),
      texture_(make_texture(gl)),
      vao_(make_vertex_array(gl)),
      vbo_(make_buffer(gl)) {
  gl.ActiveTexture(GL_TEXTURE0);
  gl.BindTexture(GL_TEXTURE_2D, texture_.id());
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_R8, atlas.width(), atlas.height(), 0, GL_RED,
                GL_UNSIGNED_BYTE, atlas.pixels().data());
  gl.GenerateMipmap(GL_TEXTURE_2D);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);

  gl.BindVertexArray(vao_.id());
  gl.BindBuffer(GL_ARRAY_BUFFER, vbo_.id());
  gl.EnableVertexAttribArray(0);
  gl.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(TextVertex),
                         text_offset(offsetof(TextVertex, position_px)));
  gl.EnableVertexAttribArray(1);
  gl.VertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, sizeof(TextVertex),
                         text_offset(offsetof(TextVertex, uv)));
  gl.EnableVertexAttribArray(2);
  gl.VertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, sizeof(TextVertex),
                         text_offset(offsetof(TextVertex, color)));
  gl.BindVertexArray(0);
}

void TextPass::draw(const std::vector<TextVertex>& vertices, glm::vec2 viewport_px) const {
  if (vertices.empty()) return;
  program_.use();
  program_.set("u_viewport_px", viewport_px);
  program_.set("u_atlas", 0);
  gl_->ActiveTexture(GL_TEXTURE0);
  gl_->BindTexture(GL_TEXTURE_2D, texture_.id());
  gl_->BindVertexArray(vao_.id());
  gl_->BindBuffer(GL_ARRAY_BUFFER, vbo_.id());
  gl_->BufferData(GL_ARRAY_BUFFER, vertices.size() * sizeof(TextVertex), vertices.data(),
                  GL_STREAM_DRAW);
  gl_->DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices.size()));
}

}  // namespace tumble::render
