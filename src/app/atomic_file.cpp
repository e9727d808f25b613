#include "app/atomic_file.hpp"

#include <cerrno>
#include <cstring>

#include <unistd.h>

namespace tumble::app {

namespace {
[[noreturn]] void fail(const std::filesystem::path& p, const char* what) {
  throw IoError("cannot " + std::string(what) + " '" + p.string() + "': " + std::strerror(errno));
}
}  // namespace

AtomicFile::AtomicFile(std::filesystem::path path) : path_(std::move(path)) {
  tmp_ = path_;
  tmp_ += ".tmp-" + std::to_string(::getpid());
  f_ = std::fopen(tmp_.c_str(), "wb");
  if (!f_) fail(tmp_, "create");
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
  const bool ok = std::fflush(f) == 0 && ::fsync(::fileno(f)) == 0;
  const int saved = errno;
  if (std::fclose(f) != 0 || !ok) {
    errno = ok ? errno : saved;
    std::error_code ec;
    std::filesystem::remove(tmp_, ec);
    fail(tmp_, "write");
  }
  if (std::rename(tmp_.c_str(), path_.c_str()) != 0) {
    const int e = errno;
    std::error_code ec;
    std::filesystem::remove(tmp_, ec);
    errno = e;
    fail(path_, "rename onto");
  }
}

void atomic_write_file(const std::filesystem::path& path, std::string_view contents) {
  AtomicFile f(path);
  f.write(contents);
  f.commit();
}

}  // namespace tumble::app
