// OSMesa backend: Mesa's software rasteriser without any window system.
// We declare the handful of OSMesa entry points ourselves instead of including
// GL/osmesa.h, because that header drags in GL/gl.h which clashes with
// glcorearb.h; the values below are copied from osmesa.h (Mesa 22).
#include <array>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/dynamic_library.hpp"
#include "render/gl_context.hpp"
#include "render/gl_functions.hpp"

namespace tumble::render {
namespace {

struct osmesa_context;
using OSMesaContext = osmesa_context*;
using CreateContextAttribsFn = OSMesaContext (*)(const int*, OSMesaContext);
using DestroyContextFn = void (*)(OSMesaContext);
using MakeCurrentFn = GLboolean (*)(OSMesaContext, void*, GLenum, GLsizei, GLsizei);
using GetProcAddressFn = void* (*)(const char*);

constexpr int kOsmesaFormat = 0x22;
constexpr int kOsmesaDepthBits = 0x30;
constexpr int kOsmesaStencilBits = 0x31;
constexpr int kOsmesaProfile = 0x33;
constexpr int kOsmesaCoreProfile = 0x34;
constexpr int kOsmesaMajor = 0x36;
constexpr int kOsmesaMinor = 0x37;

constexpr const char* kOsmesaHint = "install the Debian package libosmesa6";

class OsmesaContext final : public GlContext {
 public:
  OsmesaContext() : lib_("libOSMesa.so.8", kOsmesaHint) {
    create_ = lib_.get<CreateContextAttribsFn>("OSMesaCreateContextAttribs");
    destroy_ = lib_.get<DestroyContextFn>("OSMesaDestroyContext");
    make_current_ = lib_.get<MakeCurrentFn>("OSMesaMakeCurrent");
    get_proc_ = lib_.get<GetProcAddressFn>("OSMesaGetProcAddress");

    // We render into our own FBOs; the OSMesa buffer is only a tiny
    // placeholder default framebuffer, so it carries no depth/stencil.
    const std::array<int, 13> attribs = {kOsmesaFormat, GL_RGBA, kOsmesaDepthBits, 0,
                                         kOsmesaStencilBits, 0, kOsmesaProfile,
                                         kOsmesaCoreProfile, kOsmesaMajor, 3,
                                         kOsmesaMinor, 3, 0};
    ctx_ = create_(attribs.data(), nullptr);
    if (ctx_ == nullptr) {
      throw std::runtime_error("OSMesa: cannot create a GL 3.3 core context; " +
                               std::string(kOsmesaHint));
    }
    try {
      make_current();
      gl_ = std::make_unique<GlFunctions>(load_gl_functions(
          [](void* self, const char* name) {
            return static_cast<OsmesaContext*>(self)->get_proc_(name);
          },
          this));
    } catch (...) {
      destroy_(ctx_);
      throw;
    }
  }

  ~OsmesaContext() override { destroy_(ctx_); }

  void make_current() override {
    if (!make_current_(ctx_, placeholder_.data(), GL_UNSIGNED_BYTE, kSide, kSide)) {
      throw std::runtime_error("OSMesaMakeCurrent failed");
    }
  }

  GlBackend backend() const override { return GlBackend::osmesa; }
  std::string display() const override { return "OSMesa"; }

 private:
  static constexpr int kSide = 4;
  DynamicLibrary lib_;
  CreateContextAttribsFn create_ = nullptr;
  DestroyContextFn destroy_ = nullptr;
  MakeCurrentFn make_current_ = nullptr;
  GetProcAddressFn get_proc_ = nullptr;
  OSMesaContext ctx_ = nullptr;
  std::vector<unsigned char> placeholder_ = std::vector<unsigned char>(kSide * kSide * 4);
};

}  // namespace

std::unique_ptr<GlContext> create_osmesa_context() {
  return std::make_unique<OsmesaContext>();
}

}  // namespace tumble::render
