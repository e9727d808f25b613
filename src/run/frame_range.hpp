// `--frames A:B`: a frame range of a scene's frames.
#pragma once

#include <string>
#include <utility>

namespace tumble::run {

/// Parses "A:B" (inclusive, either end may be empty) against `count` frames.
std::pair<long, long> parse_frame_range(const std::string& spec, long count);

}  // namespace tumble::run
