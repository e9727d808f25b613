#include <filesystem>
#include <iostream>

#include "app/commands.hpp"
#include "base/input_file.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace tumble::app {

int run_action(const Action& action) {
  try {
    return action();
  } catch (const InputError& e) {  // scene and option errors, including SceneError
    std::cerr << e.what() << "\n";
    return kInputError;
  } catch (const Diverged& e) {
    std::cerr << "tumble: " << e.what() << "\n";
    return kDiverged;
  } catch (const UnreadableFile& e) {  // a directory, device, FIFO or permission denied
    std::cerr << "tumble: " << e.what() << "\n";
    return kRuntimeError;
  } catch (const io::IoError& e) {
    std::cerr << "tumble: " << e.what() << "\n";
    return kRuntimeError;
  } catch (const std::filesystem::filesystem_error& e) {  // a folder we could not create or list
    std::cerr << "tumble: " << e.what() << "\n";
    return kRuntimeError;
  } catch (const std::exception& e) {
    std::cerr << "tumble: internal error: " << e.what() << "\n";
    return kRuntimeError;
  }
}

scene::Scene load_scene_verbose(const std::filesystem::path& path, const std::vector<scene::Override>& overrides) {
  scene::Scene s = scene::load_scene(path, overrides);
  for (const std::string& w : s.warnings) std::cerr << w << "\n";
  return s;
}

}  // namespace tumble::app
