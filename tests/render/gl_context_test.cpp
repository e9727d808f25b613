// Backend selection and error reporting, without needing a working GL.
#include <gtest/gtest.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

#include "render/dynamic_library.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"

namespace tumble::render {
namespace {

TEST(GlBackend, ParsesKnownNamesOnly) {
  EXPECT_EQ(parse_gl_backend("osmesa"), GlBackend::osmesa);
  EXPECT_EQ(parse_gl_backend("egl"), GlBackend::egl);
  EXPECT_THROW(parse_gl_backend("glx"), std::invalid_argument);
  EXPECT_EQ(to_string(GlBackend::egl), "egl");
}

TEST(GlBackend, DefaultComesFromEnvironment) {
  ::setenv("TUMBLE_GL", "egl", 1);
  EXPECT_EQ(default_gl_backend(), GlBackend::egl);
  ::setenv("TUMBLE_GL", "bogus", 1);
  EXPECT_THROW(default_gl_backend(), std::invalid_argument);
  ::unsetenv("TUMBLE_GL");
  EXPECT_EQ(default_gl_backend(), GlBackend::osmesa);
}

TEST(EglDisplay, SurfacelessFirstThenDeviceZero) {
  const std::string mesa = "EGL_EXT_platform_base EGL_EXT_platform_device EGL_EXT_device_enumeration "
                           "EGL_MESA_platform_surfaceless";
  EXPECT_FALSE(choose_egl_display(mesa, std::nullopt).device_platform);
  // Older NVIDIA drivers: no surfaceless platform, so the first device.
  const EglDisplayChoice old = choose_egl_display("EGL_EXT_platform_device EGL_EXT_device_enumeration", std::nullopt);
  EXPECT_TRUE(old.device_platform);
  EXPECT_EQ(old.device, 0);
  // A device asked for goes through the device platform even beside surfaceless.
  const EglDisplayChoice two = choose_egl_display(mesa, 2);
  EXPECT_TRUE(two.device_platform);
  EXPECT_EQ(two.device, 2);
  // A name must match whole: "..._devices" is not "..._device".
  EXPECT_THROW(choose_egl_display("EGL_EXT_platform_devices EGL_EXT_device_enumeration", std::nullopt),
               std::runtime_error);
  EXPECT_THROW(choose_egl_display("EGL_MESA_platform_surfaceless", 1), std::runtime_error);
}

TEST(EglDisplay, DeviceFromEnvironment) {
  ::setenv("TUMBLE_EGL_DEVICE", "1", 1);
  EXPECT_EQ(default_egl_device(), 1);
  ::setenv("TUMBLE_EGL_DEVICE", "gpu1", 1);
  EXPECT_THROW(default_egl_device(), std::invalid_argument);
  ::setenv("TUMBLE_EGL_DEVICE", "-1", 1);
  EXPECT_THROW(default_egl_device(), std::invalid_argument);
  ::unsetenv("TUMBLE_EGL_DEVICE");
  EXPECT_FALSE(default_egl_device().has_value());
}

TEST(GlRenderer, SoftwareRasterisersAreNotHardware) {
  EXPECT_TRUE(is_software_renderer("llvmpipe (LLVM 15.0.6, 256 bits)"));
  EXPECT_TRUE(is_software_renderer("softpipe"));
  EXPECT_TRUE(is_software_renderer("Software Rasterizer"));
  EXPECT_TRUE(is_software_renderer("Mesa X11 swrast"));
  EXPECT_TRUE(is_software_renderer(""));
  EXPECT_FALSE(is_software_renderer("NVIDIA H100 80GB HBM3/PCIe/SSE2"));
  EXPECT_FALSE(is_software_renderer("AMD Radeon RX 7900 XTX (radeonsi, navi31, LLVM 15.0.6, DRM 3.54)"));
  EXPECT_FALSE(is_software_renderer("Mesa Intel(R) UHD Graphics 630 (CFL GT2)"));
}

TEST(GpuPaths, OnForHardwareUnlessTheEnvironmentSays) {
  EXPECT_EQ(parse_gpu_paths("", true), (GpuPaths{true, true}));
  EXPECT_EQ(parse_gpu_paths("auto", false), (GpuPaths{false, false}));
  EXPECT_EQ(parse_gpu_paths("none", true), (GpuPaths{false, false}));
  EXPECT_EQ(parse_gpu_paths("pbo", false), (GpuPaths{true, false}));
  EXPECT_EQ(parse_gpu_paths("fxaa,pbo", false), (GpuPaths{true, true}));
  EXPECT_THROW(parse_gpu_paths("gpu", false), std::invalid_argument);
}

TEST(DynamicLibrary, MissingLibraryNamesPackageHint) {
  try {
    DynamicLibrary lib("libtumble_not_there.so.1", "install the Debian package libfoo1");
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("libtumble_not_there.so.1"), std::string::npos) << what;
    EXPECT_NE(what.find("libfoo1"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace tumble::render
