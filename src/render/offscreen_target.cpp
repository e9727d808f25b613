#include "render/offscreen_target.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

namespace tumble::render {
namespace {

GlObject make_storage(const GlFunctions& gl, GLenum format, int samples, int w, int h) {
  GlObject rb = make_renderbuffer(gl);
  gl.BindRenderbuffer(GL_RENDERBUFFER, rb.id());
  gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, w, h);
  return rb;
}

void check_complete(const GlFunctions& gl, const char* which) {
  const GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw std::runtime_error(std::string("offscreen ") + which +
                             " framebuffer incomplete, status " + std::to_string(status));
  }
}

}  // namespace

OffscreenTarget::OffscreenTarget(const GlFunctions& gl, int width, int height, int samples)
    : gl_(gl), width_(width), height_(height), samples_(std::max(0, samples)) {
  if (width <= 0 || height <= 0) throw std::invalid_argument("offscreen target size must be > 0");
  GLint max_samples = 0;
  gl.GetIntegerv(GL_MAX_SAMPLES, &max_samples);
  samples_ = std::min(samples_, static_cast<int>(max_samples));
  if (samples_ == 1) samples_ = 0;  // 1 sample buys nothing over no MSAA

  // The resolve target doubles as the draw target when MSAA is off, so it
  // gets a depth buffer too (cheap compared to the colour readback).
  resolve_fbo_ = make_framebuffer(gl);
  gl.BindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_.id());
  resolve_color_ = make_storage(gl, GL_RGBA8, 0, width, height);
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                             resolve_color_.id());
  if (samples_ == 0) {
    resolve_depth_ = make_storage(gl, GL_DEPTH_COMPONENT24, 0, width, height);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                               resolve_depth_.id());
  }
  check_complete(gl, "resolve");

  if (samples_ > 0) {
    ms_fbo_ = make_framebuffer(gl);
    gl.BindFramebuffer(GL_FRAMEBUFFER, ms_fbo_.id());
    ms_color_ = make_storage(gl, GL_RGBA8, samples_, width, height);
    ms_depth_ = make_storage(gl, GL_DEPTH_COMPONENT24, samples_, width, height);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                               ms_color_.id());
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                               ms_depth_.id());
    check_complete(gl, "multisample");
  }
}

void OffscreenTarget::bind_for_drawing() const {
  gl_.BindFramebuffer(GL_FRAMEBUFFER, samples_ > 0 ? ms_fbo_.id() : resolve_fbo_.id());
  gl_.Viewport(0, 0, width_, height_);
}

void OffscreenTarget::read_rgba(std::vector<std::uint8_t>& rgba) {
  if (samples_ > 0) {
    gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, ms_fbo_.id());
    gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo_.id());
    gl_.BlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT,
                        GL_NEAREST);
  }
  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, resolve_fbo_.id());
  gl_.ReadBuffer(GL_COLOR_ATTACHMENT0);
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 4);

  // RGBA matches the renderbuffer, so Mesa copies rows straight out; asking
  // for GL_RGB takes its generic per-pixel conversion path (~10x slower).
  const std::size_t w = static_cast<std::size_t>(width_);
  rgba.resize(w * 4 * height_);
  gl_.ReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  if (const GLenum err = gl_.GetError(); err != GL_NO_ERROR) {
    throw std::runtime_error("glReadPixels failed, GL error " + std::to_string(err));
  }
}

}  // namespace tumble::render
