// Output that appears complete or not at all: write to a temp file beside the
// target, then rename (atomic on POSIX within one filesystem). The one temp
// name scheme of tumble, so a folder's leftovers can be recognised.
#pragma once

#include <cstdio>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace tumble::io {

/// I/O failure (permission, disk full, missing folder); the message names the path.
class IoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The one policy for every file tumble writes: `path` must be a new name or
/// an existing regular file (a symbolic link is replaced, not followed) that
/// is no input of this run, compared by device and inode (base/input_file.hpp),
/// so no spelling or link of an input passes. `what` names the output in
/// messages ("--csv", "the video"). Throws InputError (exit 2) when `path` is
/// an input, naming both; IoError (exit 1) when it is a directory, device,
/// FIFO or socket.
void check_output_target(const std::filesystem::path& path, const std::string& what);

/// An output file named by command-line `option` (e.g. "--csv"), checked before
/// any work: a non-empty file name (not a folder) in an existing, writable
/// folder, and check_output_target. Throws InputError or IoError naming the
/// option and the path.
void check_output_file(const std::string& option, const std::filesystem::path& file);

/// An output folder named by `option`, created now (with its parents) and
/// checked writable, so it fails before minutes of work. Throws IoError.
void check_output_folder(const std::string& option, const std::filesystem::path& dir);

/// `<path>.tmp-<pid>`: where an atomic write of `path` goes first.
std::filesystem::path temp_path_for(const std::filesystem::path& path);

/// The file name that `temp_path_for` gives, without its `.tmp-<pid>` tail, or
/// empty when `name` is not such a temp name (a leftover of a killed process).
std::string_view temp_target_name(std::string_view name);

/// Whether a completed file reaches the disk before the rename. Frames skip
/// it: a per-frame fsync would dominate the write, and a frame lost in a
/// crash is redrawn by the resumed run, which checks the manifest.
enum class Durability { fsync, rename_only };

/// Streams into temp_path_for(path); commit() flushes (fsyncs) and renames
/// onto `path`. Destroyed without commit, it removes the temp file. Both the
/// constructor and commit() check `path` by check_output_target.
class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path path, Durability d = Durability::fsync);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  void write(std::string_view bytes);
  void commit();

 private:
  std::filesystem::path path_, tmp_;
  Durability durability_;
  std::FILE* f_ = nullptr;
};

namespace test_hooks {
/// Called with the temp file's descriptor and path just before each fsync of
/// a commit, so a test can see that the whole file reaches the disk before
/// the rename (a crash between the two would otherwise leave a torn file).
using SyncHook = std::function<void(int fd, const std::filesystem::path& tmp)>;
void set_sync_hook(SyncHook hook);  ///< empty: none (the default)
}  // namespace test_hooks

/// Writes `contents` to `path` atomically. Throws IoError.
void atomic_write_file(const std::filesystem::path& path, std::string_view contents,
                       Durability d = Durability::fsync);

}  // namespace tumble::io
