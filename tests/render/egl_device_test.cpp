// EGL device choice: the EGL_EXT_platform_device path (the fallback where
// Mesa's surfaceless platform is missing, and --gpu N / TUMBLE_EGL_DEVICE)
// draws the same pixels as the surfaceless display. With TUMBLE_REQUIRE_GL=1
// (CI) a missing device platform fails these tests instead of skipping them:
// Mesa's EGL offers it through its software device.
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>

#include "io/image.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"
#include "test_scenes.hpp"

namespace tumble::render {
namespace {

bool gl_required() {
  const char* req = std::getenv("TUMBLE_REQUIRE_GL");
  return req != nullptr && std::string(req) == "1";
}

class EglDeviceTest : public testing::Test {
 protected:
  void SetUp() override {
    try {
      device_ = create_egl_context(0);
    } catch (const std::runtime_error& e) {
      if (gl_required()) FAIL() << "TUMBLE_REQUIRE_GL=1: EGL device 0: " << e.what();
      GTEST_SKIP() << "no EGL device platform: " << e.what();
    }
  }
  std::unique_ptr<GlContext> device_;
};

TEST_F(EglDeviceTest, DeviceZeroDrawsWhatSurfacelessDraws) {
  EXPECT_EQ(device_->display().rfind("EGL device 0 of ", 0), 0u) << device_->display();
  EXPECT_FALSE(device_->renderer().empty());
  io::Image on_device, reference;
  {
    Renderer r(*device_, 160, 120, scene::Antialias::fxaa);
    on_device = r.render(test::showcase());
  }
  // Automatic: surfaceless here, or device 0 itself where that is missing.
  const std::unique_ptr<GlContext> other = create_egl_context(std::nullopt);
  Renderer r(*other, 160, 120, scene::Antialias::fxaa);
  reference = r.render(test::showcase());
  ASSERT_EQ(on_device.rgb.size(), reference.rgb.size());
  if (device_->renderer() == other->renderer()) {
    EXPECT_TRUE(on_device.rgb == reference.rgb);
  }
}

TEST_F(EglDeviceTest, DeviceBeyondTheLastIsAnErrorListingTheDevices) {
  try {
    create_egl_context(64);
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("EGL device 64 does not exist"), std::string::npos) << what;
    EXPECT_NE(what.find("0: "), std::string::npos) << what;  // device 0 exists (SetUp made it)
  }
}

TEST_F(EglDeviceTest, EnvironmentChoosesTheDevice) {
  ::setenv("TUMBLE_EGL_DEVICE", "0", 1);
  const auto ctx = create_gl_context(GlBackend::egl);
  ::unsetenv("TUMBLE_EGL_DEVICE");
  EXPECT_EQ(ctx->display().rfind("EGL device 0 of ", 0), 0u) << ctx->display();
  EXPECT_EQ(ctx->backend(), GlBackend::egl);
}

}  // namespace
}  // namespace tumble::render
