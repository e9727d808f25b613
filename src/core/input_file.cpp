#include "core/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace tumble {

namespace {

std::string kind_of(mode_t m) {
  if (S_ISDIR(m)) return "a directory";
  if (S_ISFIFO(m)) return "a FIFO (named pipe)";
  if (S_ISCHR(m)) return "a character device";
  if (S_ISBLK(m)) return "a block device";
  if (S_ISSOCK(m)) return "a socket";
  return "not a regular file";
}

/// Closes the descriptor on every path out.
struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string read_input_file(const std::filesystem::path& path, std::size_t max_bytes, const std::string& what) {
  const std::string name = path.string() + ": " + what;
  // O_NONBLOCK: opening a FIFO with no writer must not wait for one.
  const Fd f{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC)};
  if (f.fd < 0) {
    const int e = errno;
    if (e == ENOENT) throw InputError(name + " does not exist");
    if (e == ENOTDIR) throw InputError(name + " does not exist (a component of the path is not a directory)");
    if (e == EACCES || e == EPERM) throw UnreadableFile(name + " cannot be read: permission denied");
    throw UnreadableFile(name + " cannot be opened: " + std::strerror(e));
  }
  struct stat st {};
  if (::fstat(f.fd, &st) != 0) throw UnreadableFile(name + " cannot be read: " + std::strerror(errno));
  if (!S_ISREG(st.st_mode)) throw UnreadableFile(name + " is " + kind_of(st.st_mode) + ", not a regular file");
  const auto size = static_cast<std::size_t>(st.st_size);
  if (size > max_bytes)
    throw InputError(name + " is " + std::to_string(size) + " bytes, more than the cap of " +
                     std::to_string(max_bytes) + " bytes");
  // Read at most the cap (+1 to notice a file growing past it while we read).
  std::string out(std::min(size, max_bytes) + 1, '\0');
  std::size_t got = 0;
  while (got < out.size()) {
    const ssize_t n = ::read(f.fd, out.data() + got, out.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw UnreadableFile(name + " cannot be read: " + std::strerror(errno));
    if (n == 0) break;
    got += static_cast<std::size_t>(n);
    if (got > max_bytes) throw InputError(name + " grew past the cap of " + std::to_string(max_bytes) + " bytes while being read");
    if (got == out.size()) out.resize(std::min(out.size() * 2, max_bytes + 1));
  }
  out.resize(got);
  return out;
}

}  // namespace tumble
