#include "compose/label_pins.hpp"

#include <algorithm>
#include <cmath>

#include "compose/view_layout.hpp"
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

namespace {

// The point of `box` nearest to `p`.
glm::vec2 nearest_in(const viz::Box& box, glm::vec2 p) { return {std::clamp(p.x, box.x0, box.x1), std::clamp(p.y, box.y0, box.y1)}; }

// A leader from the label's box to where `curve` comes nearest it on screen; none when they touch.
// It is an annotation: drawn in front of everything, as text is.
void add_leader(viz::View& view, const viz::TextItem& t, const viz::PolylineItem& curve, const glm::dmat4& clip_from_world,
                glm::vec2 size) {
  const viz::Box box = viz::text_box(t);
  float best = 1e30f;
  glm::vec3 end_ndc(0);
  for (const glm::dvec3& p : curve.points) {
    const glm::dvec4 clip = clip_from_world * glm::dvec4(p, 1.0);
    if (clip.w <= 0) continue;
    const glm::vec3 ndc(glm::dvec3(clip) / clip.w);
    const glm::vec2 px{(ndc.x + 1) * 0.5f * size.x, (1 - ndc.y) * 0.5f * size.y};
    const float d = glm::length(px - nearest_in(box, px));
    if (d < best) best = d, end_ndc = ndc;
  }
  if (best > 1e29f || best < 0.4f * t.size_px) return;  // no curve yet, or the label is at it
  const glm::vec2 end_px{(end_ndc.x + 1) * 0.5f * size.x, (1 - end_ndc.y) * 0.5f * size.y};
  const glm::vec2 from_px = nearest_in(box, end_px);
  const glm::vec2 to_px = end_px + (from_px - end_px) * std::min(0.5f, 0.12f * t.size_px / best);  // stop short of the curve
  // Both ends just behind the near plane, so nothing in the view hides the leader; straight on screen.
  const glm::dmat4 world_from_clip = glm::inverse(clip_from_world);
  auto near_point = [&](glm::vec2 px) {
    const glm::dvec4 w = world_from_clip * glm::dvec4(2.0 * px.x / size.x - 1, 1 - 2.0 * px.y / size.y, -0.99, 1);
    return glm::dvec3(w) / w.w;
  };
  // Thin, solid and grey, as a textbook figure's leader: in a curve's colour (dashed or not) it
  // read as one more curve or vector.
  viz::PolylineItem line{{near_point(from_px), near_point(to_px)}, viz::color_of(viz::Meaning::ink, 0.7f),
                         std::max(1.0f, t.size_px / 30), false};
  line.over_glass = true;
  view.polylines.push_back(std::move(line));
}

}  // namespace

void add_leaders(viz::View& view, const std::vector<viz::TextItem>& pinned, glm::vec2 size_px) {
  const CameraMatrices m = camera_matrices(view.camera, size_px.x / std::max(size_px.y, 1.0f));
  const glm::dmat4 clip_from_world = glm::dmat4(m.proj) * glm::dmat4(m.view);
  for (const viz::TextItem& t : pinned) {
    if (t.leader_to.empty()) continue;
    const auto curve = std::find_if(view.polylines.begin(), view.polylines.end(),
                                    [&](const viz::PolylineItem& l) { return l.name == t.leader_to; });
    if (curve != view.polylines.end()) add_leader(view, t, *curve, clip_from_world, size_px);
  }
}

}  // namespace tumble::compose
