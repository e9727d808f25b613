#include "io/atomic_file.hpp"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/error.hpp"
#include "base/input_file.hpp"

namespace tumble::io {

namespace {
constexpr std::string_view kTempTag = ".tmp-";

[[noreturn]] void fail(const std::filesystem::path& p, const char* what) {
  const int e = errno;
  throw IoError("cannot " + std::string(what) + " '" + p.string() + "': " + std::strerror(e) +
                (e == EFBIG ? " (over the file-size limit: ulimit -f, or the filesystem's largest file)" : ""));
}
test_hooks::SyncHook& sync_hook() {
  static test_hooks::SyncHook hook;
  return hook;
}

/// The temp file's bytes on the disk (the stdio buffer is flushed already).
bool sync_to_disk(std::FILE* f, const std::filesystem::path& tmp) {
  if (sync_hook()) sync_hook()(::fileno(f), tmp);
  return ::fsync(::fileno(f)) == 0;
}
}  // namespace

void test_hooks::set_sync_hook(SyncHook hook) { sync_hook() = std::move(hook); }

std::filesystem::path temp_path_for(const std::filesystem::path& path) {
  std::filesystem::path tmp = path;
  tmp += std::string(kTempTag) + std::to_string(::getpid());
  return tmp;
}

std::string_view temp_target_name(std::string_view name) {
  const std::size_t at = name.rfind(kTempTag);
  if (at == std::string_view::npos || at == 0) return {};
  const std::string_view pid = name.substr(at + kTempTag.size());
  if (pid.empty() || pid.find_first_not_of("0123456789") != std::string_view::npos) return {};
  return name.substr(0, at);
}

void check_output_target(const std::filesystem::path& path, const std::string& what) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0) return;  // a new name (or a folder we cannot search: the write says so)
  const bool link = S_ISLNK(st.st_mode);
  if (link && ::stat(path.c_str(), &st) != 0) return;  // a dangling link: replaced by the file
  if (const std::optional<std::string> input = input_with_identity(st.st_dev, st.st_ino))
    throw InputError(what + " " + path.string() + ": refusing to write over " + *input +
                     (link ? " (the path is a link to it)" : "") + ", an input of this run; choose another name");
  if (!link && !S_ISREG(st.st_mode))
    throw IoError(what + " " + path.string() + ": is " + file_kind(st.st_mode) +
                  ", not a regular file; tumble writes only regular files (give a new name)");
}

AtomicFile::AtomicFile(std::filesystem::path path, Durability d)
    : path_(std::move(path)), tmp_(temp_path_for(path_)), durability_(d) {
  check_output_target(path_, "output file");
  // The temp name is ours: whatever a killed run (or anyone) left there goes,
  // and O_EXCL makes a fresh regular file, never a FIFO or link planted in the gap.
  ::unlink(tmp_.c_str());
  const int fd = ::open(tmp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (fd < 0) fail(tmp_, "create");
  f_ = ::fdopen(fd, "wb");
  if (!f_) {
    const int e = errno;
    ::close(fd);
    ::unlink(tmp_.c_str());
    errno = e;
    fail(tmp_, "create");
  }
}

AtomicFile::~AtomicFile() {
  if (!f_) return;
  std::fclose(f_);
  std::error_code ec;
  std::filesystem::remove(tmp_, ec);
}

void AtomicFile::write(std::string_view bytes) {
  if (!f_) throw IoError("write after commit to '" + path_.string() + "'");
  if (std::fwrite(bytes.data(), 1, bytes.size(), f_) != bytes.size()) fail(tmp_, "write");
}

void AtomicFile::commit() {
  if (!f_) return;
  std::FILE* f = f_;
  f_ = nullptr;
  const bool ok = std::fflush(f) == 0 && (durability_ == Durability::rename_only || sync_to_disk(f, tmp_));
  const int saved = errno;
  if (std::fclose(f) != 0 || !ok) {
    errno = ok ? errno : saved;
    std::error_code ec;
    std::filesystem::remove(tmp_, ec);
    fail(tmp_, "write");
  }
  try {  // the target may have changed while we wrote
    check_output_target(path_, "output file");
  } catch (...) {
    std::error_code ec;
    std::filesystem::remove(tmp_, ec);
    throw;
  }
  if (std::rename(tmp_.c_str(), path_.c_str()) != 0) {
    const int e = errno;
    std::error_code ec;
    std::filesystem::remove(tmp_, ec);
    errno = e;
    fail(path_, "rename onto");
  }
}

void atomic_write_file(const std::filesystem::path& path, std::string_view contents, Durability d) {
  AtomicFile f(path, d);
  f.write(contents);
  f.commit();
}

void check_output_file(const std::string& option, const std::filesystem::path& file) {
  const std::string what = option + " " + file.string();
  const std::filesystem::path parent = file.parent_path().empty() ? "." : file.parent_path();
  std::error_code ec;
  if (file.empty()) throw InputError(option + " \"\": expected a file name, found an empty string");
  if (file.filename().empty() || std::filesystem::is_directory(file, ec))
    throw InputError(what + ": expected a file name, found a folder");
  check_output_target(file, option);
  if (!std::filesystem::is_directory(parent, ec))
    throw IoError(what + ": cannot write there: folder '" + parent.string() + "' does not exist");
  if (::access(parent.c_str(), W_OK) != 0)
    throw IoError(what + ": cannot write in folder '" + parent.string() + "': " + std::strerror(errno));
}

void check_output_folder(const std::string& option, const std::filesystem::path& dir) {
  if (dir.empty()) throw InputError(option + " \"\": expected a folder, found an empty string");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw IoError(option + " " + dir.string() + ": cannot create the folder: " + ec.message());
  if (::access(dir.c_str(), W_OK) != 0)
    throw IoError(option + " " + dir.string() + ": cannot write in the folder: " + std::strerror(errno));
}

}  // namespace tumble::io
