#include "io/folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>

#include "base/error.hpp"
#include "base/input_file.hpp"
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

[[noreturn]] void throw_in_use(const std::filesystem::path& dir, const std::string& who, const std::string& why) {
  throw InputError("output folder " + dir.string() + " is in use by " + who + why +
                   "; wait for it to finish or stop it (a killed holder frees the folder at once)");
}

/// The folder's gate (see the header), held from construction to destruction.
class Gate {
 public:
  explicit Gate(const std::filesystem::path& dir) {
    // A folder we may not read, or a filesystem that cannot lock one (NFS
    // emulates flock with write locks, which a read-only descriptor cannot
    // take): no gate; the lock file decides alone, as it did before the gate.
    fd_ = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    while (fd_ >= 0 && ::flock(fd_, LOCK_EX) != 0) {
      if (errno == EINTR) continue;
      ::close(fd_);
      fd_ = -1;
      break;
    }
  }
  ~Gate() {
    if (fd_ >= 0) ::close(fd_);  // closing drops the flock
  }
  Gate(const Gate&) = delete;
  Gate& operator=(const Gate&) = delete;

 private:
  int fd_ = -1;
};

/// The lock file, opened without following a link or waiting on a FIFO; -1 when absent and !create.
int open_lock_file(const std::filesystem::path& path, bool create) {
  const int fd = ::open(path.c_str(), (create ? O_RDWR | O_CREAT : O_RDONLY) | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK, 0644);
  if (fd < 0) {
    if (!create && errno == ENOENT) return -1;
    throw IoError("cannot open the lock file " + path.string() + ": " + std::strerror(errno));
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    throw IoError("the lock file " + path.string() + " is " + file_kind(st.st_mode) + ", not a regular file; remove it");
  }
  return fd;
}

}  // namespace

FolderLock::Holder FolderLock::refuse_if_held(const std::filesystem::path& dir, const std::string& sibling_key) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) return Holder::none;
  const Gate gate(dir);
  const int fd = open_lock_file(dir / kLockFileName, false);
  if (fd < 0) return Holder::none;  // no lock file: no holder
  if (::flock(fd, LOCK_EX | LOCK_NB) == 0) {  // free: nobody holds it (ours is dropped on close)
    ::close(fd);
    return Holder::none;
  }
  std::string key;
  const bool shards = ::flock(fd, LOCK_SH | LOCK_NB) == 0;
  const std::string who = read_holder(fd, &key);
  ::close(fd);
  if (shards && !sibling_key.empty() && key == sibling_key) return Holder::siblings;
  throw_in_use(dir, who, shards && !sibling_key.empty() ? " (rendering another scene or other settings there)" : "");
}

FolderLock::FolderLock(const std::filesystem::path& dir, Mode mode, const std::string& holder, const std::string& key) {
  const std::filesystem::path path = dir / kLockFileName;
  const Gate gate(dir);  // nobody else decides until we have
  fd_ = open_lock_file(path, true);
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
    throw_in_use(dir, who, why);
  };
  if (::flock(fd_, LOCK_EX | LOCK_NB) == 0) {  // free
    write_holder(fd_, holder, key);
    if (mode == Mode::exclusive) return;
    // Let the other shards of this render in. The conversion is not atomic,
    // but every other taker waits at the gate meanwhile.
    if (::flock(fd_, LOCK_SH | LOCK_NB) == 0) return;
    refuse("");
  }
  if (mode == Mode::exclusive) refuse("");
  if (::flock(fd_, LOCK_SH | LOCK_NB) != 0) refuse("");  // held exclusively
  std::string other_key;
  (void)read_holder(fd_, &other_key);
  errno = EWOULDBLOCK;
  if (other_key != key) refuse(" (rendering another scene or other settings there)");
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) ::close(fd_);  // closing drops the flock
}

}  // namespace tumble::io
