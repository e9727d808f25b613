// World-space coloured line segments: box edges, grids and fading trails.
#pragma once

#include <algorithm>
#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

#include "render/gl_object.hpp"
#include "render/shader_program.hpp"

namespace tumble::render {

struct LineVertex {
  glm::vec3 position;
  glm::vec4 color;
};

class LinePass {
 public:
  LinePass(const GlFunctions& gl, const std::filesystem::path& shader_dir);

  /// Draws `vertices` as GL_LINES (pairs) or GL_LINE_STRIP with the given
  /// width in pixels (clamped to what the implementation supports).
  void draw(const std::vector<LineVertex>& vertices, const glm::mat4& view_proj,
            float width_px, GLenum mode = GL_LINES) const;
  /// Widths are given for a frame 540 px high and scaled with taller frames
  /// (never thinner), so a 1080p line reads as the 540p one on a projector.
  void set_frame_height(int height_px) { scale_ = std::max(1.0f, static_cast<float>(height_px) / 540.0f); }

 private:
  const GlFunctions* gl_;
  ShaderProgram program_;
  GlObject vao_, vbo_;
  float max_width_ = 1.0f;
  float scale_ = 1.0f;
};

}  // namespace tumble::render
