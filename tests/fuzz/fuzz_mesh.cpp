// libFuzzer target: a mesh file through our structural check and, when it
// passes, assimp in the guarded child (2 s, 1 GiB per input). The first byte
// picks the format ('o' OBJ, 's' STL, 'p' PLY, 'f' OFF; others by value).
// Any input loads or throws InputError: never crashes or hangs this process.
#include <cstddef>
#include <cstdint>
#include <string>

#include "base/error.hpp"
#include "scene/mesh_file.hpp"

namespace {

tumble::scene::MeshFormat format_of(std::uint8_t b) {
  using F = tumble::scene::MeshFormat;
  switch (b) {
    case 'o': return F::obj;
    case 's': return F::stl;
    case 'p': return F::ply;
    case 'f': return F::off;
    default: return static_cast<F>(b % 4);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    (void)tumble::scene::read_mesh_bytes(bytes, format_of(data[0]), "fuzz.mesh", {2.0, std::size_t{1} << 30});
  } catch (const tumble::InputError&) {
  }
  return 0;
}
