// A particle cloud's file: plain text, one `x y z m` per line, or CSV and/or a
// header naming the columns. The cloud itself and its inertia are core's.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

#include "core/particle_cloud.hpp"

namespace tumble::io {

/// Reads a plain-text cloud: one `x y z m` per line (m, kg), `#` starts a comment;
/// or CSV (commas) and/or a header line naming the columns x, y, z, m in any order
/// (other named columns are ignored).
/// Throws InputError naming `path:line` and what was expected.
/// Only a regular file of at most `max_bytes` is read (base/input_file.hpp);
/// a file without particles is an InputError.
ParticleCloud read_cloud_file(const std::filesystem::path& path, std::size_t max_bytes = std::size_t{1} << 30);

/// Parses the same format from a string; `source_name` labels errors.
ParticleCloud parse_cloud_text(const std::string& text, const std::string& source_name);

}  // namespace tumble::io
