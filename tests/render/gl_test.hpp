// A fixture with a GL context: skips without GL, fails instead under
// TUMBLE_REQUIRE_GL=1 (CI), so a broken backend is never a silent skip there.
#pragma once

#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "render/gl_context.hpp"

namespace tumble::render::test {

class GlTest : public testing::Test {
 protected:
  void SetUp() override {
    try {
      context_ = create_gl_context(default_gl_backend());
    } catch (const std::runtime_error& e) {
      const char* req = std::getenv("TUMBLE_REQUIRE_GL");
      if (req && std::string(req) == "1") FAIL() << "TUMBLE_REQUIRE_GL=1: " << e.what();
      GTEST_SKIP() << "no GL: " << e.what();
    }
    context_->make_current();
  }
  std::unique_ptr<GlContext> context_;
};

}  // namespace tumble::render::test
