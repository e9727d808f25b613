// Reading an input file defensively: only a regular file is opened, and its
// size is checked against a cap before a byte is read, so a directory, a FIFO
// or /dev/zero given as input fails at once instead of hanging or filling memory.
// Every input is also recorded by identity (device and inode), so that no
// output of the same run can replace it under any spelling or link.
#pragma once

#include <sys/types.h>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include "base/error.hpp"

namespace tumble {
namespace base {

/// A path that exists (or may) but cannot be read: a directory, a device, a
/// FIFO, permission denied, an I/O error. The app maps it to exit code 1.
class UnreadableFile : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// What a file read is to this run: an input (a scene, cloud, mesh, image to
/// compare, font), which no output may replace, or one of tumble's own outputs
/// read back (a manifest, frames.sums, a golden under --update), which it may rewrite.
enum class ReadRole { input, own_output };

/// The whole contents of the regular file `path`, at most `max_bytes`.
/// `what` names the file in messages ("scene file", "cloud file").
/// Throws InputError when the path does not exist or the file is larger than
/// the cap, UnreadableFile when it is not a regular file or cannot be read.
/// Opens with O_NONBLOCK, so a FIFO never waits for a writer.
std::string read_input_file(const std::filesystem::path& path, std::size_t max_bytes, const std::string& what,
                            ReadRole role = ReadRole::input);

/// Like read_input_file, but nullopt when `path` does not exist (a file that
/// another process may have just removed).
std::optional<std::string> read_file_if_exists(const std::filesystem::path& path, std::size_t max_bytes,
                                               const std::string& what, ReadRole role = ReadRole::own_output);

/// "a directory", "a FIFO (named pipe)", "a character device", ...
std::string file_kind(mode_t mode);

/// Records an input read by other means (a streamed file): no output may replace it.
void note_input(dev_t dev, ino_t ino, const std::filesystem::path& path, const std::string& what_and_path);

/// "scene file scenes/a.toml" when (dev, ino) is an input of this run and that
/// input is still at its path (a removed input's inode number may be reused).
std::optional<std::string> input_with_identity(dev_t dev, ino_t ino);

}  // namespace base

// The old names, kept for every layer above.
using base::UnreadableFile;
using base::ReadRole;
using base::read_input_file;
using base::read_file_if_exists;
using base::file_kind;
using base::note_input;
using base::input_with_identity;

}  // namespace tumble
