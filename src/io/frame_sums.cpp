#include "io/frame_sums.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <sstream>

#include "base/input_file.hpp"
#include "io/atomic_file.hpp"
#include "io/png.hpp"

namespace tumble::io {

namespace {

// frames.sums holds a line of ~40 bytes per frame (at most a million frames,
// each perhaps recorded a few times over resumes).
constexpr std::size_t kMaxSumsBytes = std::size_t(256) << 20;

std::string read_frame_bytes(const std::filesystem::path& p) {
  return read_input_file(p, kMaxPngBytes, "frame", ReadRole::own_output);
}

std::string fnv1a(const std::string& bytes) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  char out[17];
  std::snprintf(out, sizeof out, "%016llx", static_cast<unsigned long long>(h));
  return out;
}

}  // namespace

void record_frame(const std::filesystem::path& frame) {
  const std::string bytes = read_frame_bytes(frame);
  const std::string line = frame.filename().string() + " " + std::to_string(bytes.size()) + " " + fnv1a(bytes) + "\n";
  const std::filesystem::path sums = frame.parent_path() / kFrameSumsName;
  check_output_target(sums, "the frame record");
  // O_NOFOLLOW | O_NONBLOCK, then fstat: a link, FIFO or device planted in the gap is refused, never waited on.
  const int fd = ::open(sums.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK, 0644);
  if (fd < 0) throw IoError("cannot write " + sums.string() + ": " + std::strerror(errno));
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    throw IoError("cannot write " + sums.string() + ": not a regular file");
  }
  const ssize_t n = ::write(fd, line.data(), line.size());
  const int e = errno;
  ::close(fd);
  if (n != static_cast<ssize_t>(line.size())) throw IoError("cannot write " + sums.string() + ": " + std::strerror(e));
}

std::map<std::string, FrameSum> read_frame_sums(const std::filesystem::path& dir) {
  std::map<std::string, FrameSum> out;
  std::istringstream in(
      read_file_if_exists(dir / kFrameSumsName, kMaxSumsBytes, "frame record", ReadRole::own_output).value_or(""));
  for (std::string line; std::getline(in, line);) {
    if (in.eof()) break;  // no newline: torn by a kill
    std::istringstream f(line);
    std::string name, hash;
    std::uint64_t size = 0;
    if (f >> name >> size >> hash && hash.size() == 16) out[name] = {size, hash};
  }
  return out;
}

std::string check_frame(const std::filesystem::path& frame, const std::map<std::string, FrameSum>& sums, int width,
                        int height) {
  struct stat st {};
  if (::lstat(frame.c_str(), &st) != 0) return "missing";
  if (S_ISLNK(st.st_mode)) return "a symbolic link";
  if (!S_ISREG(st.st_mode)) return "not a regular file";
  const auto it = sums.find(frame.filename().string());
  if (it == sums.end()) return "not recorded in " + std::string(kFrameSumsName);
  if (static_cast<std::uint64_t>(st.st_size) != it->second.size)
    return std::to_string(st.st_size) + " bytes, recorded " + std::to_string(it->second.size);
  try {
    if (fnv1a(read_frame_bytes(frame)) != it->second.hash) return "its content changed since it was written";
    const Image im = read_png(frame, ReadRole::own_output);
    if (im.width != width || im.height != height)
      return std::to_string(im.width) + "x" + std::to_string(im.height) + ", expected " + std::to_string(width) + "x" +
             std::to_string(height);
  } catch (const std::exception&) {
    return "does not decode";
  }
  return "";
}

}  // namespace tumble::io
