#include <charconv>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "app/atomic_file.hpp"
#include "app/commands.hpp"
#include "core/error.hpp"
#include "core/input_file.hpp"

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
  } catch (const IoError& e) {
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

std::string format_double(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string format_short(double v) {
  char buf[40];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general);
  return std::string(buf, r.ptr);
}

std::string json_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '"' || c == '\\') o += '\\';
    if (static_cast<unsigned char>(c) < 0x20) continue;
    o += c;
  }
  return o;
}

}  // namespace tumble::app
