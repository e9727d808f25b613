// The names of a render's frame files: frame_000000.png, frame_000001.png, ...
// (six digits, so `ls` and ffmpeg's pattern agree on the order).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace tumble::io {

/// The printf/ffmpeg pattern of the frame files, "frame_%06d.png".
inline constexpr const char* kFramePattern = "frame_%06d.png";

/// DIR/frame_<k, six digits>.png; `k` >= 0.
std::filesystem::path frame_path(const std::filesystem::path& dir, long k);

/// Whether `name` (a file name, no folder) is a frame file.
bool is_frame_file(const std::string& name);

/// k of a frame file's name "frame_<k, six digits>.png" (no folder); nothing for any other name.
std::optional<long> frame_index(const std::string& name);

}  // namespace tumble::io
