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

/// ffmpeg's output options for `format` into `tmp`: H.264 yuv420p at CRF
/// `crf`, +faststart, padded to even sizes; GIF by palettegen/paletteuse. The
/// temp name has no video extension, so the container is named (-f).
/// Bit-exact (no encoder version in the file): the same frames give the same bytes.
std::vector<std::string> ffmpeg_output_args(VideoFormat format, int crf, const std::filesystem::path& tmp);

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
                         const EncodeProgress& progress = {});

}  // namespace tumble::run
