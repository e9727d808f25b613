// Locating shaders (and optional fonts) at run time, independent of the
// working directory the binary is started from.
#pragma once

#include <filesystem>

#include "io/atomic_file.hpp"

namespace tumble::render {

/// A resource tumble needs (a shader, the font) missing or damaged: exit 1,
/// the message names the file and what provides it.
class ResourceError : public io::IoError {
 public:
  using io::IoError::IoError;
};

/// First directory containing a `shaders/` folder among: the folder of the
/// file this code is in (the executable, or the Python module's library) and
/// its parents, the executable's and its parents, then the compile-time
/// TUMBLE_SOURCE_DIR.
/// Throws ResourceError listing where it looked.
std::filesystem::path find_resource_dir();

/// DejaVuSans.ttf: `<resource_dir>/fonts/` if present, else the Debian
/// fonts-dejavu-core location. Throws ResourceError if neither exists.
std::filesystem::path find_font_file(const std::filesystem::path& resource_dir);

}  // namespace tumble::render
