// Where the keys of an explanatory video go (docs/colours.md,
// "Where the keys go"): decided once per video, from every frame's content.
#include <algorithm>
#include <cstdio>
#include <string>

#include "core/dynamics.hpp"
#include "compose/explain_views.hpp"
#include "viz/momentum_sphere.hpp"
#include "viz/poinsot.hpp"
#include "viz/scene_view.hpp"
#include "viz/text_layout.hpp"

namespace tumble::compose {

std::vector<viz::KeyEntry> ExplainViews::key_entries(std::size_t i) const {
  switch (scene_.render.explain.views[i].kind) {
    case scene::ViewKind::momentum_sphere: {  // what it draws: Π and its energy at t = 0 (conserved)
      viz::MomentumSphereInput in;
      const RigidBodyModel& m = scene_.bodies[slots_[i].body].model;
      in.inertia = m.inertia;
      if (!runs_.empty() && !runs_[0].frames.empty()) {
        in.momentum = momentum_body(runs_[0].frames[0][slots_[i].body]);
        in.two_E = in.momentum.dot(m.inv_inertia.cwiseProduct(in.momentum));
      }
      return viz::sphere_key(in);
    }
    case scene::ViewKind::poinsot: return viz::poinsot_key();
    case scene::ViewKind::plot: return {};  // the chart has its own legend
    case scene::ViewKind::world:
    case scene::ViewKind::body_frame: break;
  }
  std::vector<std::pair<std::string, viz::Color>> bodies;
  for (const scene::Body& b : scene_.bodies) {
    const Eigen::Vector3f c = 0.75f * b.color.cast<float>();
    bodies.emplace_back(b.name, viz::Color(c.x(), c.y(), c.z(), 1.0f));
  }
  return viz::bodies_key(world_.draw(), bodies);
}

namespace {

viz::Box moved(viz::Box b, float dx, float dy) { return {b.x0 + dx, b.y0 + dy, b.x1 + dx, b.y1 + dy}; }

std::string px_text(float px) {
  char s[32];
  std::snprintf(s, sizeof s, "%.1f px", static_cast<double>(px));
  return s;
}

struct Room {
  float w, h, top, margin;  // the view, px; its title's bottom; the key's margin
};

// Where a view's key goes (nullopt: nowhere): a sphere or Poinsot's
// construction moves aside for it; bodies in space only where no corner is
// clear without (the key belongs beside the bodies it explains: the camera pans).
std::optional<viz::KeySpot> view_key_spot(scene::ViewKind kind, glm::vec2 ks, Room r, const std::vector<viz::Box>& texts,
                                          const std::vector<viz::Box>& content) {
  if (kind == scene::ViewKind::momentum_sphere || kind == scene::ViewKind::poinsot)
    return viz::find_key_spot(ks, r.w, r.h, r.top, r.margin, texts, content,
                              kind == scene::ViewKind::poinsot ? r.w : viz::sphere_shift_room(r.w, r.h));
  std::vector<viz::Box> fixed = texts;
  fixed.insert(fixed.end(), content.begin(), content.end());
  if (const auto still = viz::find_key_spot(ks, r.w, r.h, r.top, r.margin, fixed, {}, 0.0f)) return still;
  return viz::find_key_spot(ks, r.w, r.h, r.top, r.margin, texts, content, r.w);
}

}  // namespace

std::vector<viz::Box> ExplainViews::overlay_boxes() const {
  std::vector<viz::Box> out;
  for (long k = 0; k < world_.clock().count(); ++k) {
    viz::DrawList dl;
    add_text(dl, k);
    for (const viz::TextItem& t : dl.texts) {
      const viz::Box b = viz::text_box(t);
      const auto same = [&](const viz::Box& o) { return o.x0 == b.x0 && o.y0 == b.y0 && o.x1 == b.x1 && o.y1 == b.y1; };
      if (std::none_of(out.begin(), out.end(), same)) out.push_back(b);
    }
  }
  return out;
}

std::vector<viz::Box> ExplainViews::frame_text_boxes(std::size_t i, long k) const {
  const std::array<double, 4> f = scene_.render.explain.views[i].viewport.value_or(std::array<double, 4>{0, 0, 1, 1});
  const float ox = static_cast<float>(f[0] * width_), oy = static_cast<float>(f[1] * height_);
  viz::DrawList dl;
  add_text(dl, k);
  std::vector<viz::Box> out;
  for (const viz::TextItem& t : dl.texts) {
    out.push_back(moved(viz::text_box(t), -ox, -oy));
    if (t.backdrop.a > 0) out.push_back(moved({t.backdrop_px.x, t.backdrop_px.y, t.backdrop_px.z, t.backdrop_px.w}, -ox, -oy));
  }
  return out;
}

// Issue 22: a key covers nothing that matters. Each view's key is placed once
// for the whole video in the first corner clear of what that view shows in
// any frame (viz::keep_clear) and of the frame's captions and badge; a sphere
// moves aside for it. A view with no such corner sends its entries to one
// frame key, placed in a corner of any view clear of every view's content.
void ExplainViews::place_keys() {
  if (!scene_.render.explain.key || runs_.empty()) return;
  const float size = viz::text_px(viz::TextRole::key, height_), margin = 0.5f * size;
  if (size < viz::kMinKeyPx) {
    notes_.push_back("keys left out: their text would be " + px_text(size) + " high, under the " +
                     px_text(viz::kMinKeyPx) + " a key needs to be read");
    return;
  }
  const long count = world_.clock().count();
  const std::vector<viz::Box> overlay = overlay_boxes();
  std::vector<viz::Box> taken;  // every view's content and keys, frame px
  std::vector<viz::KeyEntry> shown;  // by the views' own keys
  for (std::size_t i = 0; i < slots_.size(); ++i) {
    Slot& slot = slots_[i];
    const scene::ViewConfig& vc = scene_.render.explain.views[i];
    const std::array<double, 4> f = vc.viewport.value_or(std::array<double, 4>{0, 0, 1, 1});
    const float ox = static_cast<float>(f[0] * width_), oy = static_cast<float>(f[1] * height_);
    const float w = static_cast<float>(slot.width_px), h = static_cast<float>(slot.height_px);
    if (vc.kind == scene::ViewKind::plot) {
      taken.push_back({ox, oy, ox + w, oy + h});
      continue;
    }
    std::vector<viz::Box> content, texts;
    for (long k = 0; k < count; ++k) viz::keep_clear(view_at(i, k, true), w, h, content, texts);
    for (const viz::Box& b : overlay) texts.push_back(moved(b, -ox, -oy));
    viz::View head;
    const float top = viz::add_view_title(head, vc.title, w, height_);
    const std::vector<viz::KeyEntry> entries = key_entries(i);
    const glm::vec2 ks = viz::key_size(entries, size);
    slot.key = view_key_spot(vc.kind, ks, {w, h, top, margin}, texts, content);
    const float shift = slot.key ? slot.key->shift_px : 0.0f;
    for (const viz::Box& b : content) taken.push_back(moved(b, ox + shift, oy));
    for (const viz::Box& b : texts) taken.push_back(moved(b, ox, oy));
    if (slot.key) {
      viz::merge_entries(shown, entries);
      taken.push_back(moved({slot.key->top_left.x, slot.key->top_left.y, slot.key->top_left.x + ks.x,
                             slot.key->top_left.y + ks.y}, ox, oy));
    } else {
      viz::merge_entries(frame_key_, entries);
      notes_.push_back("view " + std::to_string(i) + " (" + (vc.title.empty() ? "untitled" : vc.title) +
                       "): its key joins the frame key, no corner of the view is clear of what it shows");
    }
  }
  // One colour means one thing in every view: what a view's key shows already is not repeated.
  std::vector<viz::KeyEntry> rest;
  for (const viz::KeyEntry& e : frame_key_) {
    std::vector<viz::KeyEntry> one{e};
    const std::size_t n = shown.size();
    viz::merge_entries(shown, one);
    if (shown.size() > n) rest.push_back(e);
  }
  frame_key_ = std::move(rest);
  place_frame_key(taken);
}

void ExplainViews::place_frame_key(const std::vector<viz::Box>& taken) {
  if (frame_key_.empty()) return;
  const float size = viz::text_px(viz::TextRole::key, height_);
  const glm::vec2 ks = viz::key_size(frame_key_, size);
  // First in the views whose keys it holds (beside what it explains), then in the others.
  std::vector<std::size_t> order(slots_.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_partition(order.begin(), order.end(), [&](std::size_t i) { return !slots_[i].key; });
  for (const std::size_t i : order) {
    const scene::ViewConfig& vc = scene_.render.explain.views[i];
    if (vc.kind == scene::ViewKind::plot) continue;
    const std::array<double, 4> f = vc.viewport.value_or(std::array<double, 4>{0, 0, 1, 1});
    const float ox = static_cast<float>(f[0] * width_), oy = static_cast<float>(f[1] * height_);
    std::vector<viz::Box> here;
    for (const viz::Box& b : taken) here.push_back(moved(b, -ox, -oy));
    viz::View head;
    const float top = viz::add_view_title(head, vc.title, static_cast<float>(slots_[i].width_px), height_);
    if (const auto spot = viz::find_key_spot(ks, static_cast<float>(slots_[i].width_px),
                                             static_cast<float>(slots_[i].height_px), top, 0.5f * size, here, {}, 0)) {
      frame_key_at_ = spot->top_left + glm::vec2(ox, oy);
      notes_.push_back("the frame key is in view " + std::to_string(i) + "'s corner");
      return;
    }
  }
  notes_.push_back("the frame key is left out: no corner of any view is clear of what the views show");
  frame_key_.clear();
}

}  // namespace tumble::compose
