#include "render/gl_context.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <sstream>
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

std::optional<int> default_egl_device() {
  const char* env = std::getenv("TUMBLE_EGL_DEVICE");
  if (env == nullptr || *env == '\0') return std::nullopt;
  const std::string s = env;
  if (s.size() > 4 || !std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); }))
    throw std::invalid_argument("TUMBLE_EGL_DEVICE = '" + s + "': expected a device index 0, 1, ...");
  return std::stoi(s);
}

static bool has_extension(std::string_view list, std::string_view name) {
  std::istringstream in{std::string(list)};
  for (std::string e; in >> e;)
    if (e == name) return true;
  return false;
}

EglDisplayChoice choose_egl_display(std::string_view client_extensions, std::optional<int> device) {
  const bool devices = has_extension(client_extensions, "EGL_EXT_platform_device") &&
                       has_extension(client_extensions, "EGL_EXT_device_enumeration");
  if (!device && has_extension(client_extensions, "EGL_MESA_platform_surfaceless")) return {false, 0};
  if (devices) return {true, device.value_or(0)};
  throw std::runtime_error(
      device ? "EGL device " + std::to_string(*device) +
                   " asked for, but EGL offers no EGL_EXT_platform_device with EGL_EXT_device_enumeration"
             : std::string("EGL offers neither EGL_MESA_platform_surfaceless nor EGL_EXT_platform_device"));
}

bool is_software_renderer(std::string_view gl_renderer) {
  std::string r(gl_renderer);
  std::transform(r.begin(), r.end(), r.begin(), [](unsigned char c) { return std::tolower(c); });
  for (const char* soft : {"llvmpipe", "softpipe", "swrast", "software rasterizer", "lavapipe", "swiftshader"})
    if (r.find(soft) != std::string::npos) return true;
  return r.empty();
}

GlContext::GlContext() = default;
GlContext::~GlContext() = default;

static std::string gl_string(const GlFunctions& gl, GLenum name) {
  const GLubyte* s = gl.GetString(name);
  return s ? reinterpret_cast<const char*>(s) : "";
}

std::string GlContext::version() const { return gl_string(*gl_, GL_VERSION); }
std::string GlContext::renderer() const { return gl_string(*gl_, GL_RENDERER); }
std::string GlContext::vendor() const { return gl_string(*gl_, GL_VENDOR); }

std::unique_ptr<GlContext> create_gl_context(GlBackend backend, std::optional<int> egl_device) {
  if (backend != GlBackend::egl) return create_osmesa_context();
  return create_egl_context(egl_device ? egl_device : default_egl_device());
}

}  // namespace tumble::render
