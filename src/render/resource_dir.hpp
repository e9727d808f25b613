// Locating shaders (and optional fonts) at run time, independent of the
// working directory the binary is started from.
#pragma once

#include <filesystem>

namespace tumble::render {

/// First directory containing a `shaders/` folder among: the executable's
/// directory and its parents, then the compile-time TUMBLE_SOURCE_DIR.
/// Throws std::runtime_error listing where it looked.
std::filesystem::path find_resource_dir();

/// DejaVuSans.ttf: `<resource_dir>/fonts/` if present, else the Debian
/// fonts-dejavu-core location. Throws if neither exists.
std::filesystem::path find_font_file(const std::filesystem::path& resource_dir);

}  // namespace tumble::render
