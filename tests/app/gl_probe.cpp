// Says whether a GL context can be created here (exit 0) or not (exit 1, the
// reason on stderr), without running the `tumble render` the tests check: a
// broken render must fail its tests, not turn them into skips.
#include <exception>
#include <iostream>

#include "render/gl_context.hpp"

int main() {
  try {
    const auto ctx = tumble::render::create_gl_context(tumble::render::default_gl_backend());
    std::cout << ctx->renderer() << "\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
}
