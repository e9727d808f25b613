#include "run/video.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/frame_files.hpp"

namespace tumble::run {

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

/// Exit status of a child: its code, or 128 + the signal that killed it.
struct ChildEnd {
  int code = -1, signal = 0;
};

// fork/exec without a shell: paths with spaces or quotes need no escaping.
// ffmpeg's `-progress pipe:1` lines ("frame=N") arrive on a pipe; between
// them, `stop` is polled every 100 ms so a Ctrl-C ends the encode promptly.
ChildEnd run(const std::vector<std::string>& args, const StopPoll& stop, const EncodeProgress& progress,
             int& stopped_by) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) return {};
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return {};
  }
  if (pid == 0) {
    ::dup2(fds[1], STDOUT_FILENO);
    ::execvp(argv[0], argv.data());
    ::_exit(127);
  }
  ::close(fds[1]);
  std::string line;
  for (bool open = true; open;) {
    if (stop && (stopped_by = stop()) != 0) {
      ::kill(pid, SIGTERM);
      break;
    }
    pollfd pfd{fds[0], POLLIN, 0};
    if (::poll(&pfd, 1, 100) <= 0) continue;  // timeout or EINTR: poll `stop` again
    char buf[512];
    const ssize_t n = ::read(fds[0], buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    open = n > 0;
    for (ssize_t i = 0; i < n; ++i) {
      if (buf[i] != '\n') {
        line += buf[i];
        continue;
      }
      if (progress && line.rfind("frame=", 0) == 0) progress(std::atol(line.c_str() + 6));
      line.clear();
    }
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return {};
  if (WIFSIGNALED(status)) return {-1, WTERMSIG(status)};
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, 0};
}

}  // namespace

std::vector<std::string> ffmpeg_output_args(VideoFormat format, int crf, const std::filesystem::path& tmp) {
  if (format == VideoFormat::mp4)
    // yuv420p needs even sizes; +faststart puts the index first for streaming.
    return {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf",
            std::to_string(crf), "-fflags", "+bitexact", "-flags:v", "+bitexact", "-movflags", "+faststart", "-f",
            "mp4", tmp.string()};
  return {"-vf", "split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse=dither=bayer", "-fflags",
          "+bitexact", "-f", "gif", tmp.string()};
}


VideoResult encode_video(const std::filesystem::path& frame_dir, int fps, VideoFormat format, int crf,
                         const std::filesystem::path& output, const StopPoll& stop, const EncodeProgress& progress) {
  if (format == VideoFormat::none) return {VideoResult::not_wanted, 0, {}};
  if (!ffmpeg_available())
    return {VideoResult::missing_ffmpeg, 0, std::string(kMissingFfmpeg) + "; frames were written, no video"};
  const std::filesystem::path tmp = io::temp_path_for(output);
  std::vector<std::string> args = {"ffmpeg", "-nostdin", "-y", "-loglevel", "error", "-nostats", "-progress",
                                   "pipe:1", "-framerate", std::to_string(fps), "-i",
                                   (frame_dir / io::kFramePattern).string()};
  for (std::string& a : ffmpeg_output_args(format, crf, tmp)) args.push_back(std::move(a));
  int stopped_by = 0;
  const ChildEnd end = run(args, stop, progress, stopped_by);
  if (stopped_by == 0 && stop) stopped_by = stop();
  // ffmpeg in our process group gets the terminal's Ctrl-C too, and may die of it first.
  if (stopped_by == 0 && (end.signal == SIGINT || end.signal == SIGTERM)) stopped_by = end.signal;
  std::error_code ec;
  if (stopped_by != 0 || end.code != 0) {
    std::filesystem::remove(tmp, ec);
    if (stopped_by != 0)
      return {VideoResult::interrupted, stopped_by, "interrupted while encoding " + output.filename().string()};
    const std::string how = end.signal ? "killed by signal " + std::to_string(end.signal)
                                       : "exit " + std::to_string(end.code);
    return {VideoResult::failed, 0, "ffmpeg failed (" + how + ") making " + output.string()};
  }
  std::filesystem::rename(tmp, output, ec);
  if (ec) return {VideoResult::failed, 0, "cannot rename " + tmp.string() + " to " + output.string() + ": " + ec.message()};
  return {VideoResult::made, 0, {}};
}

}  // namespace tumble::run
