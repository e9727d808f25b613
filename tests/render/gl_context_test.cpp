// Backend selection and error reporting, without needing a working GL.
#include <gtest/gtest.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

#include "render/dynamic_library.hpp"
#include "render/gl_context.hpp"

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
