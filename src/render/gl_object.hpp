// Move-only owner of one GL object name. Holds the function table of the
// context that created it, so destruction needs no global state; the context
// must outlive (and be current at destruction of) every object it made.
#pragma once

#include <utility>

#include "render/gl_functions.hpp"

namespace tumble::render {

class GlObject {
 public:
  using Deleter = void (*)(const GlFunctions&, GLuint);

  GlObject() = default;
  GlObject(const GlFunctions& gl, GLuint id, Deleter deleter)
      : gl_(&gl), id_(id), deleter_(deleter) {}
  ~GlObject() { reset(); }

  GlObject(GlObject&& o) noexcept
      : gl_(o.gl_), id_(std::exchange(o.id_, 0)), deleter_(o.deleter_) {}
  GlObject& operator=(GlObject&& o) noexcept {
    if (this != &o) {
      reset();
      gl_ = o.gl_;
      id_ = std::exchange(o.id_, 0);
      deleter_ = o.deleter_;
    }
    return *this;
  }
  GlObject(const GlObject&) = delete;
  GlObject& operator=(const GlObject&) = delete;

  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }

 private:
  void reset() {
    if (id_ != 0) deleter_(*gl_, id_);
    id_ = 0;
  }

  const GlFunctions* gl_ = nullptr;
  GLuint id_ = 0;
  Deleter deleter_ = nullptr;
};

inline GlObject make_buffer(const GlFunctions& gl) {
  GLuint id = 0;
  gl.GenBuffers(1, &id);
  return {gl, id, [](const GlFunctions& f, GLuint i) { f.DeleteBuffers(1, &i); }};
}

inline GlObject make_vertex_array(const GlFunctions& gl) {
  GLuint id = 0;
  gl.GenVertexArrays(1, &id);
  return {gl, id, [](const GlFunctions& f, GLuint i) { f.DeleteVertexArrays(1, &i); }};
}

inline GlObject make_texture(const GlFunctions& gl) {
  GLuint id = 0;
  gl.GenTextures(1, &id);
  return {gl, id, [](const GlFunctions& f, GLuint i) { f.DeleteTextures(1, &i); }};
}

inline GlObject make_framebuffer(const GlFunctions& gl) {
  GLuint id = 0;
  gl.GenFramebuffers(1, &id);
  return {gl, id, [](const GlFunctions& f, GLuint i) { f.DeleteFramebuffers(1, &i); }};
}

inline GlObject make_renderbuffer(const GlFunctions& gl) {
  GLuint id = 0;
  gl.GenRenderbuffers(1, &id);
  return {gl, id, [](const GlFunctions& f, GLuint i) { f.DeleteRenderbuffers(1, &i); }};
}

inline GlObject make_shader(const GlFunctions& gl, GLenum type) {
  return {gl, gl.CreateShader(type), [](const GlFunctions& f, GLuint i) { f.DeleteShader(i); }};
}

inline GlObject make_program(const GlFunctions& gl) {
  return {gl, gl.CreateProgram(), [](const GlFunctions& f, GLuint i) { f.DeleteProgram(i); }};
}

}  // namespace tumble::render
