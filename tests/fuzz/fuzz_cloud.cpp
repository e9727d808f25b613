// libFuzzer target: the cloud-file reader and the mass properties of what it
// reads. Any input parses, or throws InputError (including DegenerateBody).
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "core/mass_properties.hpp"
#include "core/particle_cloud.hpp"
#include "io/cloud_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const tumble::ParticleCloud c = tumble::io::parse_cloud_text(text, "fuzz.txt");
    if (!c.empty()) (void)tumble::compute_mass_properties(c, "fuzz");
  } catch (const tumble::InputError&) {
  }
  return 0;
}
