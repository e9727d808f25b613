#include "io/folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace tumble::io {

namespace {

// The holder's line: "pid N, <holder>, since <UTC time>\n<key>\n".
std::string read_holder(int fd, std::string* key) {
  char buf[4096];
  const ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
  const std::string s(buf, n > 0 ? static_cast<std::size_t>(n) : 0);
  const std::size_t nl = s.find('\n');
  if (key) *key = nl == std::string::npos ? "" : s.substr(nl + 1, s.find('\n', nl + 1) - nl - 1);
  return nl == std::string::npos ? "another process" : s.substr(0, nl);
}

void write_holder(int fd, const std::string& holder, const std::string& key) {
  char when[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(when, sizeof when, "%Y-%m-%d %H:%M:%S UTC", std::gmtime(&now));
  const std::string s = "pid " + std::to_string(::getpid()) + ", " + holder + ", since " + when + "\n" + key + "\n";
  if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, s.data(), s.size(), 0) != static_cast<ssize_t>(s.size())) {
    // The lock holds without its note; only a refused process's message is poorer.
  }
}

}  // namespace

FolderLock::FolderLock(const std::filesystem::path& dir, Mode mode, const std::string& holder, const std::string& key) {
  const std::filesystem::path path = dir / kLockFileName;
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (fd_ < 0) throw IoError("cannot open the lock file " + path.string() + ": " + std::strerror(errno));
  auto refuse = [&](const std::string& why) {
    if (errno != EWOULDBLOCK) {  // no lock support here (some network filesystems): say so, not "in use"
      const int e = errno;
      ::close(fd_);
      fd_ = -1;
      throw IoError("cannot lock " + path.string() + ": " + std::strerror(e));
    }
    std::string other_key;
    const std::string who = read_holder(fd_, &other_key);
    ::close(fd_);
    fd_ = -1;
    throw InputError("output folder " + dir.string() + " is in use by " + who + why +
                     "; wait for it to finish or stop it (a killed holder frees the folder at once)");
  };
  if (::flock(fd_, LOCK_EX | LOCK_NB) == 0) {
    write_holder(fd_, holder, key);
    if (mode == Mode::exclusive) return;
    // Let the other shards of this render in (not atomic; a second taker in the
    // gap finds our note and checks its key against ours).
    if (::flock(fd_, LOCK_SH) == 0) return;
  }
  if (mode == Mode::exclusive) refuse("");
  if (::flock(fd_, LOCK_SH | LOCK_NB) != 0) refuse("");
  std::string other_key;
  (void)read_holder(fd_, &other_key);
  errno = EWOULDBLOCK;
  if (other_key != key) refuse(" (rendering another scene or other settings there)");
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) ::close(fd_);  // closing drops the flock
}

}  // namespace tumble::io
