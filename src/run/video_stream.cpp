#include "run/video_stream.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <string>
#include <vector>

#include "io/atomic_file.hpp"

namespace tumble::run {

namespace {
constexpr int kPipeBytes = 1 << 20;
}  // namespace

VideoStream::VideoStream(int width, int height, int fps, VideoFormat format, int crf, std::filesystem::path output,
                         const VideoEncoder& encoder)
    : output_(std::move(output)), tmp_(io::temp_path_for(output_)), fps_(fps), format_(format) {
  // A dead ffmpeg must show as EPIPE from write(), not kill tumble by SIGPIPE.
  struct sigaction ignore {};
  ignore.sa_handler = SIG_IGN;
  sigemptyset(&ignore.sa_mask);
  ::sigaction(SIGPIPE, &ignore, &old_pipe_);
  if (!ffmpeg_available()) {
    status_ = {VideoResult::missing_ffmpeg, 0, std::string(kMissingFfmpeg) + "; no video made"};
    return;
  }
  std::vector<std::string> args = {"ffmpeg", "-nostdin", "-y", "-loglevel", "error", "-nostats", "-f", "rawvideo",
                                   "-pix_fmt", "rgb24", "-s", std::to_string(width) + "x" + std::to_string(height),
                                   "-framerate", std::to_string(fps), "-i", "pipe:0"};
  for (std::string& a : ffmpeg_output_args(format, crf, tmp_, encoder)) args.push_back(std::move(a));
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) {
    status_ = {VideoResult::failed, 0, "cannot make a pipe to ffmpeg"};
    return;
  }
  pid_ = ::fork();
  if (pid_ == 0) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // dies with tumble (kill -9): no orphan writing a temp file
    ::dup2(fds[0], STDIN_FILENO);  // dup2 clears O_CLOEXEC on the copy
    ::signal(SIGPIPE, SIG_DFL);     // an ignored signal would stay ignored across exec
    ::execvp(argv[0], argv.data());
    ::_exit(127);
  }
  ::close(fds[0]);
  if (pid_ < 0) {
    ::close(fds[1]);
    status_ = {VideoResult::failed, 0, "cannot start ffmpeg"};
    return;
  }
  in_ = fds[1];
  // Non-blocking: write() polls for room, so a stop signal caught by another
  // thread is seen too.
  ::fcntl(in_, F_SETFL, ::fcntl(in_, F_GETFL) | O_NONBLOCK);
  // A bigger pipe (64 KiB by default, up to /proc/sys/fs/pipe-max-size):
  // fewer wake-ups of ffmpeg and of the writer per frame. Best effort.
  ::fcntl(in_, F_SETPIPE_SZ, kPipeBytes);
}

VideoStream::~VideoStream() {
  if (pid_ > 0) abort(0);
  ::sigaction(SIGPIPE, &old_pipe_, nullptr);
}

int VideoStream::write(const io::Image& frame, const StopPoll& stop) {
  const std::uint8_t* p = frame.rgb.data();
  std::size_t left = frame.rgb.size();
  while (left > 0 && in_ >= 0 && !broken_) {
    // The stop signal's handler has no SA_RESTART: a write blocked on a full
    // pipe returns EINTR (or a short count) and the signal is seen here.
    if (stop)
      if (const int sig = stop(); sig != 0) return sig;
    const ssize_t n = ::write(in_, p, left);
    if (n < 0) {
      if (errno == EAGAIN) {  // full: ffmpeg is busy
        pollfd out{in_, POLLOUT, 0};
        ::poll(&out, 1, 100);
        continue;
      }
      if (errno == EINTR) continue;
      broken_ = true;  // EPIPE: ffmpeg exited; finish() reports how
      break;
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  if (left == 0 && !broken_) ++frames_;
  return stop ? stop() : 0;
}

int VideoStream::wait_child(const StopPoll& stop, int* stopped) {
  int status = 0;
  for (;;) {
    const pid_t r = ::waitpid(pid_, &status, stop ? WNOHANG : 0);
    if (r == pid_) break;
    if (r < 0 && errno != EINTR) {
      pid_ = -1;
      return -1;
    }
    if (r == 0) {  // still running
      if ((*stopped = stop()) != 0) return 0;
      ::poll(nullptr, 0, 20);
    }
  }
  pid_ = -1;
  if (WIFSIGNALED(status)) return -1 - WTERMSIG(status);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

VideoResult VideoStream::finish(const StopPoll& stop) {
  if (pid_ <= 0) return status_;
  ::close(in_);
  in_ = -1;
  // ffmpeg still encodes what the pipe holds (up to kPipeBytes): a stop
  // signal meanwhile ends it as one while drawing would.
  int stopped = 0;
  const int end = wait_child(stop, &stopped);
  if (stopped != 0) return abort(stopped);
  std::error_code ec;
  if (end != 0) {
    std::filesystem::remove(tmp_, ec);
    const std::string how = end < -1 ? "killed by signal " + std::to_string(-1 - end) : "exit " + std::to_string(end);
    return status_ = {VideoResult::failed, 0, "ffmpeg failed (" + how + ") making " + output_.string()};
  }
  if (const std::string bad = verify_video(tmp_, frames_, fps_, format_); !bad.empty()) {  // exit 0 is no proof
    std::filesystem::remove(tmp_, ec);
    return status_ = {VideoResult::failed, 0, "ffmpeg's " + output_.filename().string() + " failed its check (" + bad + ")"};
  }
  if (const std::string why = refused_target(output_); !why.empty()) {
    std::filesystem::remove(tmp_, ec);
    return status_ = {VideoResult::failed, 0, why};
  }
  std::filesystem::rename(tmp_, output_, ec);
  if (ec) {
    std::filesystem::remove(tmp_, ec);
    return status_ = {VideoResult::failed, 0, "cannot rename " + tmp_.string() + " to " + output_.string()};
  }
  return status_ = {VideoResult::made, 0, {}};
}

VideoResult VideoStream::abort(int signal) {
  if (pid_ > 0) {
    ::kill(pid_, SIGKILL);  // not SIGTERM: ffmpeg would finalise a partial file
    if (in_ >= 0) ::close(in_);
    in_ = -1;
    wait_child();
  }
  std::error_code ec;
  std::filesystem::remove(tmp_, ec);
  return status_ = {VideoResult::interrupted, signal,
                    "interrupted while streaming " + output_.filename().string() + "; no video kept"};
}

}  // namespace tumble::run
