// Headless GL context: one small interface, two backends (OSMesa, EGL
// surfaceless). Each backend dlopens its library and owns the GL function
// table, so nothing in the process links libGL, and this header includes no
// GL headers.
#pragma once

#include <memory>
#include <optional>
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

/// EGL device from env TUMBLE_EGL_DEVICE (an index into eglQueryDevicesEXT's
/// list, as MuJoCo's MUJOCO_EGL_DEVICE_ID), else nullopt: automatic. Throws
/// std::invalid_argument naming the variable when it is not a number >= 0.
std::optional<int> default_egl_device();

/// Which EGL display a context uses: Mesa's surfaceless platform, or one
/// device of EGL_EXT_platform_device (NVIDIA's drivers before 2022 offer only
/// that; on a multi-GPU machine it picks the GPU).
struct EglDisplayChoice {
  bool device_platform = false;
  int device = 0;  ///< with device_platform
};

/// From EGL's client extensions: a `device` asks for that device (needs
/// EGL_EXT_platform_device and EGL_EXT_device_enumeration); none prefers
/// EGL_MESA_platform_surfaceless, else device 0. Throws std::runtime_error
/// naming the missing extensions.
EglDisplayChoice choose_egl_display(std::string_view client_extensions, std::optional<int> device);

/// True for Mesa's and others' CPU rasterisers (llvmpipe, softpipe, swrast,
/// lavapipe, "Software Rasterizer"): not a hardware GPU.
bool is_software_renderer(std::string_view gl_renderer);

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
  std::string vendor() const;    ///< GL_VENDOR
  /// Which display or device: "OSMesa", "EGL surfaceless", "EGL device 1 of 2 (/dev/dri/renderD129)".
  virtual std::string display() const = 0;
  /// A hardware GPU draws (not llvmpipe and the like).
  bool hardware_gpu() const { return !is_software_renderer(renderer()); }

 protected:
  GlContext();
  std::unique_ptr<GlFunctions> gl_;  // set by the backend once current
};

/// Creates a current core-profile (>= 3.3) context. Throws std::runtime_error
/// naming the Debian package to install when the backend is unavailable.
/// `egl_device` (EGL only): nullopt = default_egl_device().
std::unique_ptr<GlContext> create_gl_context(GlBackend backend, std::optional<int> egl_device = std::nullopt);

// Backend factories (one .cpp each).
std::unique_ptr<GlContext> create_osmesa_context();
/// `device`: an index of eglQueryDevicesEXT, or nullopt for automatic (see
/// choose_egl_display); an index past the last device throws
/// std::invalid_argument listing them (a user's choice, not a missing library).
std::unique_ptr<GlContext> create_egl_context(std::optional<int> device = std::nullopt);

}  // namespace tumble::render
