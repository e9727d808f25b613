// Reading an input file defensively: only a regular file is opened, and its
// size is checked against a cap before a byte is read, so a directory, a FIFO
// or /dev/zero given as input fails at once instead of hanging or filling memory.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

#include "core/error.hpp"

namespace tumble {

/// A path that exists (or may) but cannot be read: a directory, a device, a
/// FIFO, permission denied, an I/O error. The app maps it to exit code 1.
class UnreadableFile : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The whole contents of the regular file `path`, at most `max_bytes`.
/// `what` names the file in messages ("scene file", "cloud file").
/// Throws InputError when the path does not exist or the file is larger than
/// the cap, UnreadableFile when it is not a regular file or cannot be read.
std::string read_input_file(const std::filesystem::path& path, std::size_t max_bytes, const std::string& what);

}  // namespace tumble
