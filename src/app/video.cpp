#include "app/video.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/frame_files.hpp"

namespace tumble::app {

bool ffmpeg_available() {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::string p(path);
  size_t start = 0;
  while (start <= p.size()) {
    const size_t end = p.find(':', start);
    const std::string dir = p.substr(start, end == std::string::npos ? std::string::npos : end - start);
    if (!dir.empty() && ::access((dir + "/ffmpeg").c_str(), X_OK) == 0) return true;
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return false;
}

namespace {

// fork/exec without a shell: paths with spaces or quotes need no escaping.
int run(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    ::execvp(argv[0], argv.data());
    ::_exit(127);
  }
  int status = 0;
  if (::waitpid(pid, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

std::string encode_video(const std::filesystem::path& frame_dir, int fps, VideoFormat format, int crf,
                         const std::filesystem::path& output) {
  if (format == VideoFormat::none) return {};
  if (!ffmpeg_available()) return "ffmpeg not found (Debian package: ffmpeg); frames were written, no video";
  // The temp name has no video extension, so the container is named (-f).
  const std::filesystem::path tmp = io::temp_path_for(output);
  std::vector<std::string> args = {"ffmpeg", "-nostdin", "-y", "-loglevel", "error", "-framerate",
                                   std::to_string(fps), "-i", (frame_dir / io::kFramePattern).string()};
  if (format == VideoFormat::mp4) {
    // yuv420p needs even sizes; +faststart puts the index first for streaming.
    args.insert(args.end(), {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p",
                             "-crf", std::to_string(crf), "-movflags", "+faststart", "-f", "mp4", tmp.string()});
  } else {
    args.insert(args.end(), {"-vf", "split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse=dither=bayer",
                             "-f", "gif", tmp.string()});
  }
  const int rc = run(args);
  std::error_code ec;
  if (rc != 0) {
    std::filesystem::remove(tmp, ec);
    return "ffmpeg failed (exit " + std::to_string(rc) + ") making " + output.string();
  }
  std::filesystem::rename(tmp, output, ec);
  if (ec) return "cannot rename " + tmp.string() + " to " + output.string() + ": " + ec.message();
  return {};
}

}  // namespace tumble::app
