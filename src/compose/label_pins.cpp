#include "compose/label_pins.hpp"

#include <algorithm>

#include "viz/text_layout.hpp"

namespace tumble::compose {

namespace {

// What one pinned label needs: its size and everywhere its subject went.
struct Sweep {
  glm::vec2 size{0, 0};
  viz::Box near{1e30f, 1e30f, -1e30f, -1e30f};
};

viz::Box united(const viz::Box& a, const viz::Box& b) {
  return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

}  // namespace

std::map<std::string, glm::vec2> pin_labels(const Panel& panel, const scene::FrameClock& clock, glm::vec2 size_px,
                                            float label_px, bool tip_names_further) {
  viz::Occupancy taken(static_cast<int>(size_px.x), static_cast<int>(size_px.y));
  std::map<std::string, Sweep> sweeps;
  // Every frame that shows a new moment (a hold repeats the frame before it).
  for (long k = 0; k < clock.count(); ++k) {
    if (k > 0 && clock.time(k) == clock.time(k - 1)) continue;
    viz::View v = panel.content(k);
    if (std::none_of(v.texts.begin(), v.texts.end(), viz::is_pinned_label)) continue;
    viz::label_arrow_tips(v, size_px.x, size_px.y, label_px, tip_names_further);  // the arrows' names, where each frame puts them
    for (const viz::Box& b : viz::label_obstacles(v, size_px.x, size_px.y)) taken.add(b);
    for (const viz::TextItem& t : v.texts) {
      if (!viz::is_pinned_label(t)) continue;
      const viz::Box box = viz::text_box(t);
      const bool subject = t.subject_px.z > t.subject_px.x;
      Sweep& s = sweeps[t.name];
      s.size = glm::max(s.size, glm::vec2(box.x1 - box.x0, box.y1 - box.y0));
      s.near = united(s.near, subject ? viz::Box{t.subject_px.x, t.subject_px.y, t.subject_px.z, t.subject_px.w} : box);
    }
  }
  taken.seal();
  std::map<std::string, glm::vec2> out;
  std::vector<viz::Box> pinned;  // labels pinned before keep clear of each other
  for (const auto& [name, s] : sweeps) {
    const float gap = 0.25f * s.size.y;
    const std::optional<glm::vec2> at = viz::clear_spot(s.near, s.size, gap, taken, pinned);
    if (!at) continue;
    out[name] = *at;
    pinned.push_back({at->x, at->y, at->x + s.size.x, at->y + s.size.y});
  }
  return out;
}

}  // namespace tumble::compose
