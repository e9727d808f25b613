// `tumble render --layout FILE`: the layout report of a frame range, no pixels
// (no GL, no output folder).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace tumble::run {

/// What write_layout_report wrote: frames first..last of count, at width x height px.
struct LayoutSummary {
  long first = 0, last = 0, count = 0;
  int width = 0, height = 0;
  std::vector<std::string> notes;  ///< what was left out, of which frames, and why (compose::LayoutNotes)
};

/// Simulates `s` and writes the layout report (JSON Lines: frame, view, name,
/// kind, box, visible per drawn item) of frames `frames` ("A:B", inclusive;
/// empty: all) to `path`, atomically. A bad range throws InputError.
LayoutSummary write_layout_report(const scene::Scene& s, const std::string& frames, const std::filesystem::path& path);

}  // namespace tumble::run
