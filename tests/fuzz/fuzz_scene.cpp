// libFuzzer target: the scene loader. Any input must either load or throw
// InputError (SceneError) or UnreadableFile — never crash, hang, or throw anything else.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "base/input_file.hpp"
#include "scene/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    // Cloud files resolve against a folder that does not exist: no file reads.
    (void)tumble::scene::load_scene_from_string(text, "fuzz.toml", "/nonexistent-tumble-fuzz");
  } catch (const tumble::InputError&) {
  } catch (const tumble::UnreadableFile&) {  // an absolute cloud path naming a device or folder
  }
  return 0;
}
