// Output that appears complete or not at all: write to a temp file beside the
// target, then rename (atomic on POSIX within one filesystem).
#pragma once

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace tumble::app {

/// I/O failure (permission, disk full, missing folder); the message names the path.
class IoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Streams into `<path>.tmp-<pid>`; commit() flushes, fsyncs and renames onto
/// `path`. Destroyed without commit, it removes the temp file.
class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  void write(std::string_view bytes);
  void commit();

 private:
  std::filesystem::path path_, tmp_;
  std::FILE* f_ = nullptr;
};

/// Writes `contents` to `path` atomically. Throws IoError.
void atomic_write_file(const std::filesystem::path& path, std::string_view contents);

}  // namespace tumble::app
