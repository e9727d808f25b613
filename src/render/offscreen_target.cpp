#include "render/offscreen_target.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include "io/atomic_file.hpp"

namespace tumble::render {
namespace {

GlObject make_storage(const GlFunctions& gl, GLenum format, int samples, int w, int h) {
  GlObject rb = make_renderbuffer(gl);
  gl.BindRenderbuffer(GL_RENDERBUFFER, rb.id());
  gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, w, h);
  return rb;
}

/// A framebuffer GL could not make is a size (or sample count) past what this
/// GL can hold, not a bug: said so, with the limit, as an I/O-class error.
void check_complete(const GlFunctions& gl, const char* which, int w, int h, int samples) {
  const GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status == GL_FRAMEBUFFER_COMPLETE) return;
  const GLenum error = gl.GetError();
  GLint max_size = 0;
  gl.GetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  throw io::IoError("cannot make the " + std::to_string(w) + "x" + std::to_string(h) + " offscreen " + which +
                    " framebuffer" + (samples > 0 ? " with " + std::to_string(samples) + " MSAA samples" : "") +
                    " (GL status " + std::to_string(status) +
                    (error == GL_OUT_OF_MEMORY ? ", GL_OUT_OF_MEMORY" : "") + "; this GL's largest renderbuffer is " +
                    std::to_string(max_size) + " px): lower --width/--height or --msaa, or give the process more memory");
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
  check_complete(gl, "resolve", width, height, 0);

  if (samples_ > 0) {
    ms_fbo_ = make_framebuffer(gl);
    gl.BindFramebuffer(GL_FRAMEBUFFER, ms_fbo_.id());
    ms_color_ = make_storage(gl, GL_RGBA8, samples_, width, height);
    ms_depth_ = make_storage(gl, GL_DEPTH_COMPONENT24, samples_, width, height);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                               ms_color_.id());
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                               ms_depth_.id());
    check_complete(gl, "multisample", width, height, samples_);
  }
}

void OffscreenTarget::bind_for_drawing() const {
  gl_.BindFramebuffer(GL_FRAMEBUFFER, samples_ > 0 ? ms_fbo_.id() : resolve_fbo_.id());
  gl_.Viewport(0, 0, width_, height_);
}

void OffscreenTarget::resolve() {
  if (samples_ > 0) {
    gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, ms_fbo_.id());
    gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo_.id());
    gl_.BlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT,
                        GL_NEAREST);
  }
  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, resolve_fbo_.id());
  gl_.ReadBuffer(GL_COLOR_ATTACHMENT0);
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 4);
}

void OffscreenTarget::read_rgba(std::vector<std::uint8_t>& rgba) {
  resolve();
  // RGBA matches the renderbuffer, so Mesa copies rows straight out; asking
  // for GL_RGB takes its generic per-pixel conversion path (~10x slower).
  rgba.resize(frame_bytes());
  gl_.ReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  if (const GLenum err = gl_.GetError(); err != GL_NO_ERROR) {
    throw std::runtime_error("glReadPixels failed, GL error " + std::to_string(err));
  }
}

void OffscreenTarget::start_read() {
  if (queued_ == 2) throw std::logic_error("OffscreenTarget: two reads queued already; finish_read() first");
  resolve();
  GlObject& pbo = pbo_[next_];
  if (pbo.id() == 0) {
    pbo = make_buffer(gl_);
    gl_.BindBuffer(GL_PIXEL_PACK_BUFFER, pbo.id());
    gl_.BufferData(GL_PIXEL_PACK_BUFFER, static_cast<GLsizeiptr>(frame_bytes()), nullptr, GL_STREAM_READ);
  }
  gl_.BindBuffer(GL_PIXEL_PACK_BUFFER, pbo.id());
  gl_.ReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);  // into the PBO
  gl_.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  if (const GLenum err = gl_.GetError(); err != GL_NO_ERROR) {
    throw std::runtime_error("glReadPixels into a PBO failed, GL error " + std::to_string(err));
  }
  next_ = 1 - next_;
  ++queued_;
}

bool OffscreenTarget::finish_read(std::vector<std::uint8_t>& rgba) {
  if (queued_ == 0) return false;
  const int oldest = queued_ == 2 ? next_ : 1 - next_;
  gl_.BindBuffer(GL_PIXEL_PACK_BUFFER, pbo_[oldest].id());
  // Waits only if the GPU has not finished that copy yet.
  const void* p = gl_.MapBufferRange(GL_PIXEL_PACK_BUFFER, 0, static_cast<GLsizeiptr>(frame_bytes()), GL_MAP_READ_BIT);
  if (p == nullptr) {
    gl_.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    throw std::runtime_error("glMapBufferRange of the read-back failed, GL error " + std::to_string(gl_.GetError()));
  }
  rgba.resize(frame_bytes());
  std::memcpy(rgba.data(), p, frame_bytes());
  gl_.UnmapBuffer(GL_PIXEL_PACK_BUFFER);
  gl_.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  --queued_;
  return true;
}

void OffscreenTarget::begin_post_pass() {
  if (post_texture_.id() == 0) {
    post_texture_ = make_texture(gl_);
    gl_.BindTexture(GL_TEXTURE_2D, post_texture_.id());
    gl_.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width_, height_, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    post_fbo_ = make_framebuffer(gl_);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, post_fbo_.id());
    gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, post_texture_.id(), 0);
    check_complete(gl_, "post-pass", width_, height_, 0);
  }
  resolve();
  gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, post_fbo_.id());
  gl_.BlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_.id());
  gl_.Viewport(0, 0, width_, height_);
  gl_.ActiveTexture(GL_TEXTURE0);
  gl_.BindTexture(GL_TEXTURE_2D, post_texture_.id());
}

}  // namespace tumble::render
