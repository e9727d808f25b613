// Videos from PNG frame sequences, by running ffmpeg as a program.
#pragma once

#include <filesystem>
#include <string>

#include "scene/scene.hpp"

namespace tumble::app {

using scene::VideoFormat;

/// True when an `ffmpeg` executable is on PATH.
bool ffmpeg_available();

/// Encodes DIR/frame_%06d.png (frames 0..count-1) at `fps` into `output`
/// (written to a temporary name, then renamed). H.264 yuv420p, CRF `crf`,
/// +faststart, padded to even dimensions; GIF with palettegen/paletteuse.
/// Returns an empty string on success, else what went wrong.
std::string encode_video(const std::filesystem::path& frame_dir, int fps, VideoFormat format, int crf,
                         const std::filesystem::path& output);

}  // namespace tumble::app
