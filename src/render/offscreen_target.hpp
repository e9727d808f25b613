// Offscreen render target: an optional multisampled FBO that is resolved
// (glBlitFramebuffer) into a single-sample FBO we read back.
#pragma once

#include <cstdint>
#include <vector>

#include "render/gl_object.hpp"
#include "io/image.hpp"

namespace tumble::render {

class OffscreenTarget {
 public:
  /// `samples` of 0 renders single-sampled; other values are clamped to
  /// GL_MAX_SAMPLES. Throws if the framebuffer is incomplete.
  OffscreenTarget(const GlFunctions& gl, int width, int height, int samples);

  /// Binds the framebuffer the scene should be drawn into.
  void bind_for_drawing() const;
  /// Resolves MSAA (if any) and reads back RGBA8, bottom row first (GL's
  /// order), into `out`, reusing its storage (fresh multi-MB buffers cost
  /// page faults per frame). render::finish_frame makes the image of it.
  void read_rgba(std::vector<std::uint8_t>& out);

  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }

 private:
  const GlFunctions& gl_;
  int width_, height_, samples_;
  GlObject ms_fbo_, ms_color_, ms_depth_;        // multisampled (samples_ > 0)
  GlObject resolve_fbo_, resolve_color_, resolve_depth_;  // single-sample
};

}  // namespace tumble::render
