#include "run/video.hpp"

#include <fcntl.h>
#include <sys/prctl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
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
             int& stopped_by, std::string* all = nullptr) {
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
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // dies with tumble (kill -9): no orphan writing a temp file
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
    if (all && n > 0) all->append(buf, static_cast<std::size_t>(n));
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

// What a program prints on stdout (no shell: any path is one argument), "" when it cannot run.
std::string capture(const std::vector<std::string>& args) {
  std::string out;
  int stopped_by = 0;
  std::vector<std::string> a = args;
  const ChildEnd end = run(a, {}, {}, stopped_by, &out);
  return end.code == 0 ? out : std::string();
}

// "a/100%/b" for ffmpeg's image2 pattern, which reads '%' as a format directive.
std::string escape_pattern(const std::string& s) {
  std::string out;
  for (char c : s) out += c == '%' ? std::string("%%") : std::string(1, c);
  return out;
}

}  // namespace

std::string verify_video(const std::filesystem::path& video, long frames, int fps, VideoFormat format) {
  const std::string out = capture({"ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                                   "stream=codec_type,nb_read_frames:format=duration", "-of",
                                   "default=noprint_wrappers=1", video.string()});
  auto field = [&](const std::string& key) {
    const std::size_t at = out.find(key + "=");
    return at == std::string::npos ? std::string() : out.substr(at + key.size() + 1, out.find('\n', at) - at - key.size() - 1);
  };
  if (out.empty()) return "ffprobe cannot read it (or is missing: Debian package ffmpeg)";
  if (field("codec_type") != "video") return "no video stream";
  const long n = std::atol(field("nb_read_frames").c_str());
  // GIF merges identical consecutive frames: fewer is fine there, never more.
  if (scene::video_format(format).every_frame ? n != frames : (n < 1 || n > frames))
    return std::to_string(n) + " frames, expected " + std::to_string(frames);
  const double d = std::atof(field("duration").c_str()), want = static_cast<double>(frames) / fps;
  if (!(std::abs(d - want) <= 0.1 * want + 2.0 / fps))
    return "lasts " + field("duration") + " s, expected " + std::to_string(want) + " s";
  return "";
}

VideoEncoder x264_encoder(int cores) {
  // scripts/video_presets.sh's table (docs/rendering.md, "Video encoder"): at CRF 18 the
  // fastest preset whose PSNR and SSIM against the frames are at least those
  // of x264's default (medium): ultrafast, at a quarter of medium's CPU time
  // and about twice its file size. One thread on 2 cores, where tumble draws
  // and finishes frames on both (a second x264 thread bought nothing, with
  // the serial stream and again with the overlapped one); else x264's own count.
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

std::string refused_target(const std::filesystem::path& video) {
  try {
    io::check_output_target(video, "the video");
  } catch (const std::exception& e) {
    return e.what();
  }
  return {};
}

std::vector<std::string> ffmpeg_output_args(VideoFormat format, int crf, const std::filesystem::path& tmp,
                                            const VideoEncoder& encoder) {
  const scene::VideoFormatRow& row = scene::video_format(format);
  std::vector<std::string> args = {"-vf", std::string(row.filter)};
  if (row.h264) {
    args.insert(args.end(), {"-c:v", encoder.codec, "-pix_fmt", "yuv420p"});
    if (encoder.codec == "h264_nvenc") {
      // NVENC's constant-quality mode at the CRF's number: not the same
      // scale as x264's CRF, close at 18 (unmeasured here: no NVIDIA GPU).
      for (const char* a : {"-rc", "vbr", "-b:v", "0"}) args.emplace_back(a);
      args.insert(args.end(), {"-cq", std::to_string(crf)});
    } else {
      args.insert(args.end(), {"-crf", std::to_string(crf), "-threads", std::to_string(encoder.threads)});
    }
    if (!encoder.preset.empty()) args.insert(args.end(), {"-preset", encoder.preset});
  }
  std::istringstream flags{std::string(row.flags)};
  for (std::string a; flags >> a;) args.push_back(a);
  args.insert(args.end(), {"-f", std::string(row.name), tmp.string()});
  return args;
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
                                   escape_pattern(frame_dir.string()) + "/" + io::kFramePattern};
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
  // ffmpeg's exit status is no proof (a full disk fails the trailer, exit 0 or
  // not): the video replaces an earlier one only once ffprobe reads it whole.
  long frames = 0;
  while (std::filesystem::exists(io::frame_path(frame_dir, frames), ec)) ++frames;
  if (const std::string bad = verify_video(tmp, frames, fps, format); !bad.empty()) {
    std::filesystem::remove(tmp, ec);
    return {VideoResult::failed, 0, "ffmpeg's " + output.filename().string() + " failed its check (" + bad + ")" +
                                        (std::filesystem::exists(output, ec) ? "; the earlier video is kept" : "")};
  }
  if (const std::string why = refused_target(output); !why.empty()) {
    std::filesystem::remove(tmp, ec);
    return {VideoResult::failed, 0, why};
  }
  std::filesystem::rename(tmp, output, ec);
  if (ec) return {VideoResult::failed, 0, "cannot rename " + tmp.string() + " to " + output.string() + ": " + ec.message()};
  return {VideoResult::made, 0, {}};
}

}  // namespace tumble::run
