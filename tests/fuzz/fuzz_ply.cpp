// libFuzzer target: the PLY vertex reader. Any input parses or throws
// InputError — never crashes, hangs, or throws anything else.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "base/error.hpp"
#include "scene/ply_vertices.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    (void)tumble::scene::read_ply_vertices(in, "fuzz.ply");
  } catch (const tumble::InputError&) {
  }
  return 0;
}
