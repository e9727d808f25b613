#include "run/layout_run.hpp"

#include <sstream>
#include <utility>
#include <vector>

#include "io/atomic_file.hpp"
#include "compose/layout_report.hpp"
#include "compose/frame_builder.hpp"
#include "compose/layout_notes.hpp"
#include "run/frame_range.hpp"

namespace tumble::run {

LayoutSummary write_layout_report(const scene::Scene& s, const std::string& frames, const std::filesystem::path& path) {
  const scene::OutputConfig& out = s.render.output;
  const long count = scene::frame_clock(s, out.fps).count();
  const auto [first, last] = frames.empty() ? std::pair<long, long>{0, count - 1} : parse_frame_range(frames, count);
  const std::vector<scene::Run> runs = scene::simulate_runs(s, count, out.fps);
  const compose::FrameBuilder builder(s, runs, out.fps, out.width, out.height);
  std::ostringstream text;
  compose::LayoutNotes notes;
  for (long k = first; k <= last; ++k) {
    const viz::DrawList dl = builder.build(k);
    notes.add(k, dl.notes);
    compose::write_layout(text, k, compose::layout_items(dl, out.width, out.height));
  }
  io::atomic_write_file(path, text.str());
  return {first, last, count, out.width, out.height, notes.lines()};
}

}  // namespace tumble::run
