// Draws a viz::DrawList into an offscreen MSAA framebuffer and returns the
// pixels. Meshes, shaders and the font atlas are created once per Renderer.
#pragma once

#include <filesystem>
#include <vector>

#include "render/font_atlas.hpp"
#include "render/gl_context.hpp"
#include "render/image.hpp"
#include "render/instanced_mesh.hpp"
#include "render/line_pass.hpp"
#include "render/offscreen_target.hpp"
#include "render/resource_dir.hpp"
#include "render/shader_program.hpp"
#include "render/text_pass.hpp"
#include "render/view_batches.hpp"
#include "render/view_layout.hpp"
#include "viz/draw_list.hpp"

namespace tumble::render {

class Renderer {
 public:
  /// `context` must outlive the renderer. `msaa` is 0 (off), 2 or 4 (clamped
  /// to GL_MAX_SAMPLES). Shaders come from `resource_dir`/shaders.
  Renderer(GlContext& context, int width, int height, int msaa = 4,
           const std::filesystem::path& resource_dir = find_resource_dir());
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  /// Renders all views (grid of `columns`, row-major) plus overlays.
  Image render(const viz::DrawList& frame);
  /// Same, into `out`, reusing its pixel storage (cheaper in a frame loop).
  void render(const viz::DrawList& frame, Image& out);

  int width() const { return target_.width(); }
  int height() const { return target_.height(); }
  int samples() const { return target_.samples(); }  ///< after clamping

 private:
  void draw_view(const viz::View& view, const PixelRect& rect, const glm::vec3& background);
  void draw_background(const glm::vec3& background);
  void draw_separators(const std::vector<PixelRect>& rects, const glm::vec3& color);
  void draw_meshes(const ViewBatches& batches, const CameraMatrices& cam);
  void draw_text(const std::vector<viz::TextItem>& items, const std::string& label,
                 const PixelRect& rect);
  void set_viewport(const PixelRect& rect);

  GlContext& context_;
  const GlFunctions& gl_;
  FontAtlas font_;
  OffscreenTarget target_;
  ShaderProgram mesh_program_, background_program_;
  InstancedMesh cube_, cylinder_, cone_, sphere_;
  LinePass lines_;
  TextPass text_;
  GlObject empty_vao_;  // core profile needs a bound VAO even for attribute-less draws
};

}  // namespace tumble::render
