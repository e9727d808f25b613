// Screen-space text: glyph quads from a FontAtlas, sampled from its texture.
#pragma once

#include <filesystem>
#include <vector>

#include "render/font_atlas.hpp"
#include "render/gl_object.hpp"
#include "render/shader_program.hpp"

namespace tumble::render {

class TextPass {
 public:
  /// Uploads the atlas once (mipmapped so small text stays smooth).
  TextPass(const GlFunctions& gl, const std::filesystem::path& shader_dir,
           const FontAtlas& atlas);

  /// Draws quads laid out in pixels of a viewport of the given size.
  void draw(const std::vector<TextVertex>& vertices, glm::vec2 viewport_px) const;

 private:
  const GlFunctions* gl_;
  ShaderProgram program_;
  GlObject texture_, vao_, vbo_;
};

}  // namespace tumble::render
