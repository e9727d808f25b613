// `tumble assemble`'s pipeline: the shards of a render (`tumble render
// --frames A:B`, each with its manifest part) checked to add up, then one
// manifest.json and the video, as a single run would have made them.
#pragma once

#include <filesystem>
#include <optional>

#include "run/listener.hpp"
#include "scene/frame_settings.hpp"

namespace tumble::run {

/// Assembles the shards in `dir` into a video of `video` (default: the one the
/// shards were rendered for). Throws InputError naming every reason the parts
/// do not make one whole render, io::IoError when `dir` is not a folder.
Outcome assemble(const std::filesystem::path& dir, std::optional<scene::VideoFormat> video, Listener& l);

}  // namespace tumble::run
