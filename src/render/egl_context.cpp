// EGL backend without a display server or pbuffer: the context is made
// current with EGL_NO_SURFACE and draws into our FBOs. The display is Mesa's
// surfaceless platform, or a device of EGL_EXT_platform_device (older NVIDIA
// drivers have only that; several GPUs are told apart by it).
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <algorithm>
#include <array>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/dynamic_library.hpp"
#include "render/gl_context.hpp"
#include "render/gl_functions.hpp"

namespace tumble::render {
namespace {

constexpr const char* kEglHint = "install the Debian packages libegl1 and libegl-mesa0";

std::string to_hex(EGLint v) {
  constexpr char digits[] = "0123456789abcdef";
  std::string s;
  for (int shift = 12; shift >= 0; shift -= 4) s += digits[(v >> shift) & 0xf];
  return s;
}

class EglContext final : public GlContext {
 public:
  explicit EglContext(std::optional<int> device) : lib_("libEGL.so.1", kEglHint) {
    get_proc_ = lib_.get<PFNEGLGETPROCADDRESSPROC>("eglGetProcAddress");
    auto query_string = lib_.get<PFNEGLQUERYSTRINGPROC>("eglQueryString");
    get_error_ = lib_.get<PFNEGLGETERRORPROC>("eglGetError");
    destroy_context_ = lib_.get<PFNEGLDESTROYCONTEXTPROC>("eglDestroyContext");
    make_current_ = lib_.get<PFNEGLMAKECURRENTPROC>("eglMakeCurrent");

    const char* client = query_string(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    const EglDisplayChoice choice = choose_egl_display(client ? client : "", device);
    display_ = choice.device_platform ? device_display(choice.device) : surfaceless_display();
    create_context();
    try {
      make_current();
      gl_ = std::make_unique<GlFunctions>(load_gl_functions(
          [](void* self, const char* name) {
            return reinterpret_cast<void*>(static_cast<EglContext*>(self)->get_proc_(name));
          },
          this));
    } catch (...) {
      release();
      throw;
    }
  }

  // The display is deliberately not terminated: EGL displays are
  // process-wide singletons, and terminating would kill other live contexts.
  ~EglContext() override { release(); }

  void make_current() override {
    if (!make_current_(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      throw std::runtime_error("eglMakeCurrent (no surface) failed on " + display_name_);
    }
  }

  GlBackend backend() const override { return GlBackend::egl; }
  std::string display() const override { return display_name_; }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error(display_name_ + ": " + what + " (EGL error 0x" + to_hex(get_error_()) + "); " + kEglHint);
  }

  EGLDisplay surfaceless_display() {
    display_name_ = "EGL surfaceless";
    auto get_platform_display = lib_.get<PFNEGLGETPLATFORMDISPLAYPROC>("eglGetPlatformDisplay");
    const EGLDisplay d = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA,
                                              reinterpret_cast<void*>(EGL_DEFAULT_DISPLAY), nullptr);
    if (d == EGL_NO_DISPLAY) fail("no surfaceless display");
    return d;
  }

  // Extension entry points come from eglGetProcAddress, not the library.
  template <class Fn>
  Fn ext(const char* name) const {
    auto f = reinterpret_cast<Fn>(get_proc_(name));
    if (f == nullptr) throw std::runtime_error(std::string("EGL lacks ") + name + "; " + kEglHint);
    return f;
  }

  /// The device's DRM node or name, for messages and the manifest.
  std::string device_label(EGLDeviceEXT dev) const {
    auto query = ext<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
    const char* exts = query(dev, EGL_EXTENSIONS);
    const std::string e = exts ? exts : "";
    if (e.find("EGL_MESA_device_software") != std::string::npos) return "software";
    if (e.find("EGL_EXT_device_drm") != std::string::npos)
      if (const char* file = query(dev, EGL_DRM_DEVICE_FILE_EXT)) return file;
    get_error_();  // a failed query leaves an error behind; it is not ours to report
    return "unnamed";
  }

  EGLDisplay device_display(int index) {
    auto query_devices = ext<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
    EGLint count = 0;
    if (!query_devices(0, nullptr, &count)) fail("eglQueryDevicesEXT failed");
    std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(std::max(count, 0)));
    if (count > 0 && !query_devices(count, devices.data(), &count)) fail("eglQueryDevicesEXT failed");
    if (index < 0 || index >= count) {
      std::string list;
      for (EGLint i = 0; i < count; ++i) list += (i ? ", " : "") + std::to_string(i) + ": " + device_label(devices[i]);
      throw std::invalid_argument("EGL device " + std::to_string(index) + " does not exist (TUMBLE_EGL_DEVICE / --gpu); " +
                               std::to_string(count) + " device(s)" + (list.empty() ? "" : ": " + list));
    }
    display_name_ = "EGL device " + std::to_string(index) + " of " + std::to_string(count) + " (" +
                    device_label(devices[index]) + ")";
    auto get_platform_display = lib_.get<PFNEGLGETPLATFORMDISPLAYPROC>("eglGetPlatformDisplay");
    const EGLDisplay d = get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[index], nullptr);
    if (d == EGL_NO_DISPLAY) fail("no display for the device");
    return d;
  }

  void create_context() {
    auto initialize = lib_.get<PFNEGLINITIALIZEPROC>("eglInitialize");
    auto choose_config = lib_.get<PFNEGLCHOOSECONFIGPROC>("eglChooseConfig");
    auto bind_api = lib_.get<PFNEGLBINDAPIPROC>("eglBindAPI");
    auto create = lib_.get<PFNEGLCREATECONTEXTPROC>("eglCreateContext");
    EGLint major = 0, minor = 0;
    if (!initialize(display_, &major, &minor)) fail("eglInitialize failed");
    const std::array<EGLint, 5> config_attribs = {EGL_SURFACE_TYPE, 0, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!choose_config(display_, config_attribs.data(), &config, 1, &count) || count < 1) {
      fail("no OpenGL-capable config");
    }
    if (!bind_api(EGL_OPENGL_API)) fail("eglBindAPI(EGL_OPENGL_API) failed");
    const std::array<EGLint, 7> context_attribs = {
        EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
        EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    context_ = create(display_, config, EGL_NO_CONTEXT, context_attribs.data());
    if (context_ == EGL_NO_CONTEXT) fail("cannot create a GL 3.3 core context");
  }

  void release() {
    make_current_(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    destroy_context_(display_, context_);
  }

  DynamicLibrary lib_;
  PFNEGLGETPROCADDRESSPROC get_proc_ = nullptr;
  PFNEGLGETERRORPROC get_error_ = nullptr;
  PFNEGLDESTROYCONTEXTPROC destroy_context_ = nullptr;
  PFNEGLMAKECURRENTPROC make_current_ = nullptr;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  std::string display_name_ = "EGL";
};

}  // namespace

std::unique_ptr<GlContext> create_egl_context(std::optional<int> device) {
  return std::make_unique<EglContext>(device);
}

}  // namespace tumble::render
