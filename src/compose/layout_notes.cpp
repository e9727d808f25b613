#include "compose/layout_notes.hpp"

#include <algorithm>

#include "compose/frame_builder.hpp"
#include "scene/frame_clock.hpp"
#include "scene/frame_runs.hpp"

namespace tumble::compose {

namespace {

constexpr std::size_t kRangesShown = 4;

std::string range_text(const std::pair<long, long>& r) {
  return r.first == r.second ? std::to_string(r.first) : std::to_string(r.first) + "-" + std::to_string(r.second);
}

}  // namespace

void LayoutNotes::add(long frame, const std::vector<std::string>& notes) {
  for (const std::string& n : notes) {
    auto e = std::find_if(entries_.begin(), entries_.end(), [&](const Entry& x) { return x.note == n; });
    if (e == entries_.end()) {
      entries_.push_back({n, {}});
      e = entries_.end() - 1;
    }
    if (!e->ranges.empty() && e->ranges.back().second + 1 == frame) e->ranges.back().second = frame;
    else if (e->ranges.empty() || e->ranges.back().second != frame) e->ranges.emplace_back(frame, frame);
  }
}

std::vector<std::string> LayoutNotes::lines() const {
  std::vector<std::string> out;
  for (const Entry& e : entries_) {
    std::vector<std::pair<long, long>> r = e.ranges;
    std::sort(r.begin(), r.end());
    const bool one = r.size() == 1 && r[0].first == r[0].second;
    std::string where = one ? "frame " : "frames ";
    for (std::size_t i = 0; i < std::min(r.size(), kRangesShown); ++i) where += (i ? ", " : "") + range_text(r[i]);
    if (r.size() > kRangesShown) where += " and " + std::to_string(r.size() - kRangesShown) + " more stretches";
    out.push_back(e.note + " (" + where + ")");
  }
  return out;
}

LayoutNotes check_layout(const scene::Scene& s) {
  const scene::OutputConfig& out = s.render.output;
  const long count = scene::frame_clock(s, out.fps).count();
  const std::vector<scene::Run> runs = scene::simulate_runs(s, count, out.fps);
  const FrameBuilder builder(s, runs, out.fps, out.width, out.height);
  LayoutNotes notes;
  const long good = runs.size() == 1 ? static_cast<long>(runs[0].frames.size()) : count;
  for (long k = 0; k < good; ++k) notes.add(k, builder.build(k).notes);
  return notes;
}

}  // namespace tumble::compose
