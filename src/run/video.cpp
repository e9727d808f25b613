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
#include "render/worker_threads.hpp"

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

VideoEncoder x264_encoder(int cores) {
  // scripts/video_presets.sh's table (README, "Video encode"): at CRF 18 the
  // fastest preset whose PSNR and SSIM against the frames are at least those
  // of x264's default (medium): ultrafast, at a quarter of medium's CPU time
  // and about twice its file size. One thread on 2 cores, where tumble draws
  // on the other (a second x264 thread bought nothing); else x264's own count.
  return {"libx264", "ultrafast", cores <= 2 ? 1 : 0};
}

VideoEncoder default_video_encoder() { return x264_encoder(render::usable_cores()); }

namespace {

/// Whether ffmpeg can open h264_nvenc here: listed is not enough (Debian's
/// ffmpeg lists it on every machine; it needs NVIDIA's libnvidia-encode).
bool nvenc_works() {
  const std::vector<std::string> args = {"ffmpeg", "-nostdin", "-loglevel", "quiet", "-f", "lavfi", "-i",
                                         "color=size=256x256:rate=30:duration=0.5", "-frames:v", "16", "-c:v",
                                         "h264_nvenc", "-f", "null", "-"};
  int stopped_by = 0;
  return run(args, {}, {}, stopped_by).code == 0;
}

}  // namespace

VideoEncoder choose_video_encoder(const std::string& gl_vendor, int cores) {
  if (gl_vendor.find("NVIDIA") != std::string::npos && ffmpeg_available() && nvenc_works())
    return {"h264_nvenc", "p4", 0};
  return x264_encoder(cores);
}

std::vector<std::string> ffmpeg_output_args(VideoFormat format, int crf, const std::filesystem::path& tmp,
                                            const VideoEncoder& encoder) {
  if (format == VideoFormat::mp4) {
    // yuv420p needs even sizes; +faststart puts the index first for streaming.
    std::vector<std::string> args = {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", encoder.codec, "-pix_fmt",
                                     "yuv420p"};
    if (encoder.codec == "h264_nvenc") {
      // NVENC's constant-quality mode at the CRF's number: not the same
      // scale as x264's CRF, close at 18 (unmeasured here: no NVIDIA GPU).
      for (const char* a : {"-rc", "vbr", "-b:v", "0"}) args.emplace_back(a);
      args.insert(args.end(), {"-cq", std::to_string(crf)});
    } else {
      args.insert(args.end(), {"-crf", std::to_string(crf), "-threads", std::to_string(encoder.threads)});
    }
    if (!encoder.preset.empty()) args.insert(args.end(), {"-preset", encoder.preset});
    for (const char* a : {"-fflags", "+bitexact", "-flags:v", "+bitexact", "-movflags", "+faststart", "-f", "mp4"})
      args.emplace_back(a);
    args.push_back(tmp.string());
    return args;
  }
  return {"-vf", "split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse=dither=bayer", "-fflags",
          "+bitexact", "-f", "gif", tmp.string()};
}

VideoResult encode_video(const std::filesystem::path& frame_dir, int fps, VideoFormat format, int crf,
                         const std::filesystem::path& output, const StopPoll& stop, const EncodeProgress& progress,
                         const VideoEncoder& encoder) {
  if (format == VideoFormat::none) return {VideoResult::not_wanted, 0, {}};
  if (!ffmpeg_available())
    return {VideoResult::missing_ffmpeg, 0, std::string(kMissingFfmpeg) + "; frames were written, no video"};
  const std::filesystem::path tmp = io::temp_path_for(output);
  std::vector<std::string> args = {"ffmpeg", "-nostdin", "-y", "-loglevel", "error", "-nostats", "-progress",
                                   "pipe:1", "-framerate", std::to_string(fps), "-i",
                                   (frame_dir / io::kFramePattern).string()};
  // Alone on the machine (the frames are drawn already): all cores.
  VideoEncoder alone = encoder;
  alone.threads = 0;
  for (std::string& a : ffmpeg_output_args(format, crf, tmp, alone)) args.push_back(std::move(a));
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
