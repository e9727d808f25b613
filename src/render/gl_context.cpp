#include "render/gl_context.hpp"

#include <cstdlib>
#include <stdexcept>

#include "render/gl_functions.hpp"

namespace tumble::render {

GlBackend parse_gl_backend(std::string_view name) {
  if (name == "osmesa") return GlBackend::osmesa;
  if (name == "egl") return GlBackend::egl;
  throw std::invalid_argument("unknown GL backend '" + std::string(name) +
                              "' (expected osmesa or egl)");
}

std::string_view to_string(GlBackend backend) {
  return backend == GlBackend::egl ? "egl" : "osmesa";
}

GlBackend default_gl_backend() {
  const char* env = std::getenv("TUMBLE_GL");
  return (env != nullptr && *env != '\0') ? parse_gl_backend(env) : GlBackend::osmesa;
}

GlContext::GlContext() = default;
GlContext::~GlContext() = default;

static std::string gl_string(const GlFunctions& gl, GLenum name) {
  const GLubyte* s = gl.GetString(name);
  return s ? reinterpret_cast<const char*>(s) : "";
}

std::string GlContext::version() const { return gl_string(*gl_, GL_VERSION); }
std::string GlContext::renderer() const { return gl_string(*gl_, GL_RENDERER); }

std::unique_ptr<GlContext> create_gl_context(GlBackend backend) {
  return backend == GlBackend::egl ? create_egl_context() : create_osmesa_context();
}

}  // namespace tumble::render
