#include "base/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <mutex>
#include <vector>

namespace tumble::base {

namespace {

/// Closes the descriptor on every path out.
struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

struct Input {
  dev_t dev;
  ino_t ino;
  std::string path;  // absolute, to see later whether the file is still there
  std::string name;
};

/// Whether `i` still names a live file: a test process (or a long run) may
/// remove an input, and the kernel then hands its inode number to a new file.
bool still_there(const Input& i) {
  struct stat st {};
  return ::stat(i.path.c_str(), &st) == 0 && st.st_dev == i.dev && st.st_ino == i.ino;
}

std::mutex inputs_mutex;
std::vector<Input>& inputs() {
  static std::vector<Input> v;
  return v;
}

std::string read_open_file(int fd, std::size_t max_bytes, const std::string& name, std::size_t size) {
  if (size > max_bytes)
    throw InputError(name + " is " + std::to_string(size) + " bytes, more than the cap of " +
                     std::to_string(max_bytes) + " bytes");
  // Read at most the cap (+1 to notice a file growing past it while we read).
  std::string out(std::min(size, max_bytes) + 1, '\0');
  std::size_t got = 0;
  while (got < out.size()) {
    const ssize_t n = ::read(fd, out.data() + got, out.size() - got);
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

/// The open regular file, or nullopt-like -1 when it does not exist and `missing_ok`.
int open_regular(const std::filesystem::path& path, const std::string& name, bool missing_ok, struct stat& st) {
  // O_NONBLOCK: opening a FIFO with no writer must not wait for one.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) {
    const int e = errno;
    if (e == ENOENT && missing_ok) return -1;
    if (e == ENOENT) throw InputError(name + " does not exist");
    if (e == ENOTDIR) throw InputError(name + " does not exist (a component of the path is not a directory)");
    if (e == EACCES || e == EPERM) throw UnreadableFile(name + " cannot be read: permission denied");
    throw UnreadableFile(name + " cannot be opened: " + std::strerror(e));
  }
  const Fd guard{fd};
  if (::fstat(fd, &st) != 0) throw UnreadableFile(name + " cannot be read: " + std::strerror(errno));
  if (!S_ISREG(st.st_mode)) throw UnreadableFile(name + " is " + file_kind(st.st_mode) + ", not a regular file");
  return ::dup(fd);  // the guard closes its own copy
}

}  // namespace

std::string file_kind(mode_t m) {
  if (S_ISDIR(m)) return "a directory";
  if (S_ISFIFO(m)) return "a FIFO (named pipe)";
  if (S_ISCHR(m)) return "a character device";
  if (S_ISBLK(m)) return "a block device";
  if (S_ISSOCK(m)) return "a socket";
  if (S_ISLNK(m)) return "a symbolic link";
  return "not a regular file";
}

std::optional<std::string> read_file_if_exists(const std::filesystem::path& path, std::size_t max_bytes,
                                               const std::string& what, ReadRole role) {
  const std::string name = path.string() + ": " + what;
  struct stat st {};
  const Fd f{open_regular(path, name, true, st)};
  if (f.fd < 0) return std::nullopt;
  if (role == ReadRole::input) note_input(st.st_dev, st.st_ino, path, what + " " + path.string());
  return read_open_file(f.fd, max_bytes, name, static_cast<std::size_t>(st.st_size));
}

std::string read_input_file(const std::filesystem::path& path, std::size_t max_bytes, const std::string& what,
                            ReadRole role) {
  const std::string name = path.string() + ": " + what;
  struct stat st {};
  const Fd f{open_regular(path, name, false, st)};
  if (role == ReadRole::input) note_input(st.st_dev, st.st_ino, path, what + " " + path.string());
  return read_open_file(f.fd, max_bytes, name, static_cast<std::size_t>(st.st_size));
}

void note_input(dev_t dev, ino_t ino, const std::filesystem::path& path, const std::string& what_and_path) {
  std::error_code ec;
  std::filesystem::path abs = std::filesystem::absolute(path, ec);
  if (ec) abs = path;
  const std::lock_guard<std::mutex> lock(inputs_mutex);
  std::vector<Input>& v = inputs();
  v.erase(std::remove_if(v.begin(), v.end(), [&](const Input& i) { return i.dev == dev && i.ino == ino; }), v.end());
  v.push_back({dev, ino, abs.string(), what_and_path});
}

std::optional<std::string> input_with_identity(dev_t dev, ino_t ino) {
  const std::lock_guard<std::mutex> lock(inputs_mutex);
  std::vector<Input>& v = inputs();
  for (auto it = v.begin(); it != v.end(); ++it) {
    if (it->dev != dev || it->ino != ino) continue;
    if (still_there(*it)) return it->name;
    v.erase(it);  // removed since it was read: its inode number now belongs to another file
    return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace tumble::base
