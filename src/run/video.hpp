// Videos from PNG frame sequences, by running ffmpeg as a program.
#pragma once

#include <csignal>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace tumble::run {

using scene::VideoFormat;

/// True when an `ffmpeg` executable is on PATH.
bool ffmpeg_available();

inline constexpr const char* kMissingFfmpeg = "ffmpeg not found on PATH (Debian package: ffmpeg)";

/// The H.264 encoder of an mp4 and its settings.
struct VideoEncoder {
  std::string codec = "libx264";  ///< or "h264_nvenc"
  std::string preset;             ///< x264's or NVENC's preset
  int threads = 0;                ///< x264 threads; 0 = x264's own (1.5 per core)
};

/// libx264 at the preset and threads chosen by scripts/video_presets.sh's
/// table (docs/rendering.md, "Video encoder"), for `cores`: the cores this process may
/// use (render::usable_cores), never --jobs, so that x264's thread count, and
/// with it the video's bytes, do not depend on --jobs.
VideoEncoder x264_encoder(int cores);

/// x264_encoder for the cores this process may use (render::usable_cores).
VideoEncoder default_video_encoder();

/// h264_nvenc when `gl_vendor` is NVIDIA's and ffmpeg offers the encoder and
/// can open it (a 16-frame trial encode), else x264_encoder(cores) (usable cores, not --jobs).
VideoEncoder choose_video_encoder(const std::string& gl_vendor, int cores);

/// ffmpeg's output options for `format` into `tmp`, from its row
/// (scene::video_format): its filter (mp4: padded to even sizes; GIF:
/// palettegen/paletteuse), H.264 yuv420p at CRF `crf` by `encoder` where the
/// row says h264, its flags (bit-exact: the same frames give the same bytes).
/// The temp name has no video extension, so the container is named (-f).
std::vector<std::string> ffmpeg_output_args(VideoFormat format, int crf, const std::filesystem::path& tmp,
                                            const VideoEncoder& encoder = default_video_encoder());

/// "" when `video` holds a video stream of `frames` frames (a row not
/// `every_frame`, GIF: 1..frames, it merges repeats) lasting about frames / fps, as ffprobe counts them;
/// else what is wrong.
std::string verify_video(const std::filesystem::path& video, long frames, int fps, VideoFormat format);
/// Why `video` may not be written (io::check_output_target: an input of this
/// run, or not a regular file), or "" when it may.
std::string refused_target(const std::filesystem::path& video);

/// How an encode ended. `signal` is SIGINT/SIGTERM when it was interrupted
/// (tumble asked to stop, or ffmpeg itself got the terminal's Ctrl-C).
struct VideoResult {
  enum Status { made, not_wanted, missing_ffmpeg, failed, interrupted } status = made;
  int signal = 0;
  std::string message;  ///< what went wrong, empty when made
  bool ok() const { return status == made || status == not_wanted; }
};

/// Polled while ffmpeg runs: returns the stop signal received (0 = none).
using StopPoll = std::function<int()>;
/// Called with the number of frames encoded so far.
using EncodeProgress = std::function<void(long)>;

/// Encodes DIR/frame_%06d.png (frames 0..count-1) at `fps` into `output`
/// (written to a temporary name, then renamed). H.264 yuv420p, CRF `crf`,
/// +faststart, padded to even dimensions; GIF with palettegen/paletteuse.
/// A stop signal seen by `stop` kills ffmpeg and removes its temp file.
VideoResult encode_video(const std::filesystem::path& frame_dir, int fps, VideoFormat format, int crf,
                         const std::filesystem::path& output, const StopPoll& stop = {},
                         const EncodeProgress& progress = {}, const VideoEncoder& encoder = default_video_encoder());

}  // namespace tumble::run
