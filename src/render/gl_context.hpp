// Headless GL context: one small interface, two backends (OSMesa, EGL
// surfaceless). Each backend dlopens its library and owns the GL function
// table, so nothing in the process links libGL, and this header includes no
// GL headers.
#pragma once

#include <memory>
#include <string>
#include <string_view>


namespace tumble::render {

struct GlFunctions;  // render/gl_functions.hpp; kept out of this header

enum class GlBackend { osmesa, egl };

/// "osmesa" | "egl" (case-sensitive); throws std::invalid_argument otherwise.
GlBackend parse_gl_backend(std::string_view name);
std::string_view to_string(GlBackend backend);

/// Backend from env TUMBLE_GL if set, else OSMesa.
GlBackend default_gl_backend();

class GlContext {
 public:
  virtual ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  /// Binds the context to the calling thread (renderer calls it per frame).
  virtual void make_current() = 0;
  virtual GlBackend backend() const = 0;

  /// Entry points loaded for this context (include render/gl_functions.hpp).
  const GlFunctions& gl() const { return *gl_; }
  std::string version() const;   ///< GL_VERSION
  std::string renderer() const;  ///< GL_RENDERER

 protected:
  GlContext();
  std::unique_ptr<GlFunctions> gl_;  // set by the backend once current
};

/// Creates a current core-profile (>= 3.3) context. Throws std::runtime_error
/// naming the Debian package to install when the backend is unavailable.
std::unique_ptr<GlContext> create_gl_context(GlBackend backend);

// Backend factories (one .cpp each).
std::unique_ptr<GlContext> create_osmesa_context();
std::unique_ptr<GlContext> create_egl_context();

}  // namespace tumble::render
