#include "render/gl_functions.hpp"

#include <stdexcept>
#include <string>

namespace tumble::render {

GlFunctions load_gl_functions(GlProcResolver resolve, void* user) {
  GlFunctions gl;
  // Function pointers come back as void*; the cast to the exact PFN type is
  // the documented way to use GetProcAddress results.
#define TUMBLE_GL_LOAD(type, name, symbol)                                    \
  gl.name = reinterpret_cast<type>(resolve(user, symbol));                    \
  if (gl.name == nullptr) {                                                   \
    throw std::runtime_error(std::string("GL function not available: ") +     \
                             symbol);                                         \
  }
  TUMBLE_GL_FUNCTIONS(TUMBLE_GL_LOAD)
#undef TUMBLE_GL_LOAD
  return gl;
}

}  // namespace tumble::render
