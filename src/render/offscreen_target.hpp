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

  /// Overlapped read-back through two pixel-buffer objects: start_read()
  /// resolves and queues the copy of the drawn frame, returning at once (a
  /// GPU copies while the CPU builds the next frame); finish_read() maps the
  /// oldest queued copy into `out` (same bytes as read_rgba), false when none
  /// is queued. At most two are queued: a third start_read() throws.
  void start_read();
  bool finish_read(std::vector<std::uint8_t>& out);
  int reads_queued() const { return queued_; }

  /// For a post pass (GL FXAA): resolves, copies the frame into a texture
  /// bound to unit 0 and binds the resolve framebuffer to draw the result over it.
  void begin_post_pass();

  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }

 private:
  const GlFunctions& gl_;
  int width_, height_, samples_;
  GlObject ms_fbo_, ms_color_, ms_depth_;        // multisampled (samples_ > 0)
  GlObject resolve_fbo_, resolve_color_, resolve_depth_;  // single-sample
  GlObject pbo_[2];   // made on the first start_read()
  int next_ = 0, queued_ = 0;
  GlObject post_fbo_, post_texture_;  // made on the first begin_post_pass()
  void resolve();
  std::size_t frame_bytes() const { return static_cast<std::size_t>(width_) * 4 * height_; }
};

}  // namespace tumble::render
