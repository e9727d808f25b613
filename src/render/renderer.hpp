// Draws a viz::DrawList into an offscreen framebuffer (MSAA or FXAA) and returns the
// pixels. Meshes, shaders and the font atlas are created once per Renderer.
// No GL headers leak from here: the GL state lives in Renderer::Impl.
#pragma once

#include <filesystem>
#include <memory>

#include "render/fxaa.hpp"
#include "render/gl_context.hpp"
#include "io/image.hpp"
#include "render/resource_dir.hpp"
#include "viz/draw_list.hpp"

namespace tumble::render {

class Renderer {
 public:
  /// `context` must outlive the renderer. `msaa` is 0 (off), 2 or 4 (clamped
  /// to GL_MAX_SAMPLES); `fxaa` adds FXAA on the read-back frame and smooth
  /// lines (text is left as drawn, already anti-aliased). Shaders come from
  /// `resource_dir`/shaders, the font from `resource_dir`/fonts or the system
  /// DejaVu. Throws std::runtime_error on missing resources, shader errors or
  /// an incomplete framebuffer.
  Renderer(GlContext& context, int width, int height, int msaa = 4, bool fxaa = false,
           const std::filesystem::path& resource_dir = find_resource_dir());
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  /// Renders all views (grid of `columns`, row-major, each view's label in
  /// its top-left corner) plus the frame overlay texts. Makes the context
  /// current on the calling thread.
  io::Image render(const viz::DrawList& frame);
  /// Same, into `out`, reusing its pixel storage (cheaper in a frame loop).
  void render(const viz::DrawList& frame, io::Image& out);
  /// Same, stopping at the read-back: finish_frame(out, ...) makes the image
  /// (with FXAA when it is on), e.g. on a FrameEncoder thread while the next
  /// frame draws. The bytes equal render(frame, image)'s.
  void render(const viz::DrawList& frame, RawFrame& out);

  int width() const;
  int height() const;
  int samples() const;  ///< MSAA samples after clamping (0 = off)
  bool fxaa() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tumble::render
