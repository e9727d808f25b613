// EGL backend on Mesa's surfaceless platform: no display server, no pbuffer;
// the context is made current with EGL_NO_SURFACE and draws into our FBOs.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <array>
#include <memory>
#include <stdexcept>
#include <string>

#include "render/dynamic_library.hpp"
#include "render/gl_context.hpp"
#include "render/gl_functions.hpp"

namespace tumble::render {
namespace {

constexpr const char* kHint = "install the Debian packages libegl1 and libegl-mesa0";

class EglContext final : public GlContext {
 public:
  EglContext() : lib_("libEGL.so.1", kHint) {
    get_proc_ = lib_.get<PFNEGLGETPROCADDRESSPROC>("eglGetProcAddress");
    auto get_platform_display =
        lib_.get<PFNEGLGETPLATFORMDISPLAYPROC>("eglGetPlatformDisplay");
    auto initialize = lib_.get<PFNEGLINITIALIZEPROC>("eglInitialize");
    auto choose_config = lib_.get<PFNEGLCHOOSECONFIGPROC>("eglChooseConfig");
    auto bind_api = lib_.get<PFNEGLBINDAPIPROC>("eglBindAPI");
    auto create_context = lib_.get<PFNEGLCREATECONTEXTPROC>("eglCreateContext");
    destroy_context_ = lib_.get<PFNEGLDESTROYCONTEXTPROC>("eglDestroyContext");
    make_current_ = lib_.get<PFNEGLMAKECURRENTPROC>("eglMakeCurrent");
    auto get_error = lib_.get<PFNEGLGETERRORPROC>("eglGetError");

    auto fail = [&](const char* what) {
      throw std::runtime_error(std::string("EGL surfaceless: ") + what + " (EGL error 0x" +
                               to_hex(get_error()) + "); " + kHint);
    };

    display_ = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA,
                                    reinterpret_cast<void*>(EGL_DEFAULT_DISPLAY), nullptr);
    if (display_ == EGL_NO_DISPLAY) fail("no surfaceless display");
    EGLint major = 0, minor = 0;
    if (!initialize(display_, &major, &minor)) fail("eglInitialize failed");

    const std::array<EGLint, 5> config_attribs = {EGL_SURFACE_TYPE, 0, EGL_RENDERABLE_TYPE,
                                                  EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!choose_config(display_, config_attribs.data(), &config, 1, &count) || count < 1) {
      fail("no OpenGL-capable config");
    }
    if (!bind_api(EGL_OPENGL_API)) fail("eglBindAPI(EGL_OPENGL_API) failed");
    const std::array<EGLint, 7> context_attribs = {
        EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
        EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    context_ = create_context(display_, config, EGL_NO_CONTEXT, context_attribs.data());
    if (context_ == EGL_NO_CONTEXT) fail("cannot create a GL 3.3 core context");
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
      throw std::runtime_error("eglMakeCurrent (surfaceless) failed");
    }
  }

  GlBackend backend() const override { return GlBackend::egl; }

 private:
  static std::string to_hex(EGLint v) {
    constexpr char digits[] = "0123456789abcdef";
    std::string s;
    for (int shift = 12; shift >= 0; shift -= 4) s += digits[(v >> shift) & 0xf];
    return s;
  }

  void release() {
    make_current_(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    destroy_context_(display_, context_);
  }

  DynamicLibrary lib_;
  PFNEGLGETPROCADDRESSPROC get_proc_ = nullptr;
  PFNEGLDESTROYCONTEXTPROC destroy_context_ = nullptr;
  PFNEGLMAKECURRENTPROC make_current_ = nullptr;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<GlContext> create_egl_context() { return std::make_unique<EglContext>(); }

}  // namespace tumble::render
