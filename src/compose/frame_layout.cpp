#include "compose/frame_layout.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "compose/view_layout.hpp"
#include "viz/captions.hpp"

namespace tumble::compose {

namespace {

// A key beside its content leaves the content at least this much of the view's width.
constexpr float kMinContentShare = 0.45f;

std::string px(float v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.0f px", static_cast<double>(v));
  return s;
}

std::string view_name(std::size_t i, const ViewNeeds& v) { return compose::view_name(i, v.kind, v.title); }

// The caption strip: as tall as the longest caption wraps (viz::caption_items
// places each inside it), with a row above the captions for the status badge
// (speed, paused, a flip's mark) at its right, so the captions keep the
// frame's whole width and the badge is read at a size a hall can see.
void plan_captions(const FrameNeeds& n, FramePlan& p) {
  const float fh = static_cast<float>(n.height);
  float top = fh;
  for (const std::string& c : n.captions)
    for (const viz::TextItem& t : viz::caption_items(c, 1.0f, n.width, n.height))
      if (t.backdrop.a > 0) top = std::min(top, t.backdrop_px.y - 0.25f * viz::text_px(viz::TextRole::caption, n.height, 1));
  if (const auto badge = viz::speed_badge(n.badge, true, n.width, n.height, true, n.text_scale)) {
    p.badge_y = (top < fh ? top : badge->position_px.y + 1.3f * badge->size_px) - 1.25f * badge->size_px;
    if (top >= fh) p.badge_y = badge->position_px.y;
    top = p.badge_y - 0.15f * badge->size_px;
  }
  if (top >= fh) return;
  const float h = fh - std::floor(top);
  if (n.caption_side == FrameNeeds::CaptionSide::top) {
    p.captions = {0, 0, static_cast<float>(n.width), h};
    p.caption_shift = -(fh - h);
  } else {
    p.captions = {0, fh - h, static_cast<float>(n.width), fh};
  }
}

// The views' area: the frame less the caption and frame-key strips.
viz::Box views_area(const FrameNeeds& n, const FramePlan& p) {
  viz::Box a{0, 0, static_cast<float>(n.width), static_cast<float>(n.height)};
  if (p.captions.y1 > p.captions.y0) {
    if (p.captions.y0 <= 0) a.y0 = p.captions.y1;  // the strip at the top
    else a.y1 = p.captions.y0;
  }
  if (p.frame_key_box.y1 > p.frame_key_box.y0 && !p.frame_key_in_corner) a.y1 = std::min(a.y1, p.frame_key_box.y0);
  return a;
}

bool has_entry(const std::vector<viz::KeyEntry>& key, const viz::KeyEntry& e) {
  return std::any_of(key.begin(), key.end(), [&](const viz::KeyEntry& x) { return viz::same_entry(x, e); });
}

// `e` into the frame key, given by view i (an entry already there notes view i too).
void add_frame_entry(FramePlan& p, const viz::KeyEntry& e, std::size_t i) {
  const auto at = std::find_if(p.frame_key.begin(), p.frame_key.end(), [&](const viz::KeyEntry& x) { return viz::same_entry(x, e); });
  const auto j = static_cast<std::size_t>(at - p.frame_key.begin());
  if (at == p.frame_key.end()) p.frame_key.push_back(e);
  p.frame_key_from.resize(p.frame_key.size());
  p.frame_key_from[j].push_back(i);
}

// When a view's key only repeats entries other views show too (three momentum
// spheres side by side), the frame gets one key with every view's entries,
// like a figure's legend, and the views none: a colour means one thing
// throughout, and no view gives its width to a copy. Returns each view's own key.
std::vector<std::vector<viz::KeyEntry>> split_keys(const FrameNeeds& n, FramePlan& p) {
  std::vector<std::vector<viz::KeyEntry>> own;
  for (const ViewNeeds& v : n.views) own.push_back(v.key);
  const auto shown_elsewhere = [&](std::size_t i, const viz::KeyEntry& e) {
    for (std::size_t j = 0; j < n.views.size(); ++j)
      if (j != i && has_entry(n.views[j].key, e)) return true;
    return false;
  };
  bool repeated = false;
  for (std::size_t i = 0; i < n.views.size() && !repeated; ++i)
    repeated = !n.views[i].key.empty() && std::all_of(n.views[i].key.begin(), n.views[i].key.end(),
                                                      [&](const viz::KeyEntry& e) { return shown_elsewhere(i, e); });
  if (!repeated) return own;
  for (std::size_t i = 0; i < own.size(); ++i) {
    for (const viz::KeyEntry& e : own[i]) add_frame_entry(p, e, i);
    if (!own[i].empty()) p.frame_key_views.push_back(i);
    own[i].clear();
  }
  return own;
}

// A key beside a view that would leave its content under kFrameKeyShare of
// the view's width (bigger text, narrower views) goes to the frame key
// instead, in rows above the captions: the content keeps its width.
constexpr float kFrameKeyShare = 0.62f;

std::array<double, 4> declared_extent(const FrameNeeds& n);

void move_wide_keys(const FrameNeeds& n, FramePlan& p, std::vector<std::vector<viz::KeyEntry>>& keys) {
  const float key_px = viz::text_px(viz::TextRole::key, n.height, n.text_scale), pad = 0.5f * key_px;
  if (key_px < viz::kMinKeyPx) return;
  const std::array<double, 4> e = declared_extent(n);
  const int cols = std::max(1, std::min(n.columns, static_cast<int>(n.views.size())));
  for (std::size_t i = 0; i < n.views.size(); ++i) {
    if (keys[i].empty()) continue;
    const double share = n.views[i].viewport ? (*n.views[i].viewport)[2] / (e[2] - e[0]) : 1.0 / cols;
    const float w = static_cast<float>(share * n.width);
    // A lone view (a classic scene) gives width more freely: its body is most often short of height.
    const float keep = n.views.size() == 1 && !n.views[i].viewport ? kMinContentShare : kFrameKeyShare;
    if (w - viz::key_size(keys[i], key_px).x - 3 * pad >= keep * w) continue;
    for (const viz::KeyEntry& k : keys[i]) add_frame_entry(p, k, i);
    p.frame_key_views.push_back(i);
    keys[i].clear();
  }
}


// The views' bottom-right corner that no view declares: under the views that
// reach the right edge (a column of side views shorter than the frame), as x,
// y, width, height fractions; none when the declared views do not fill the
// unit square or something stands there.
std::optional<std::array<double, 4>> free_corner(const FrameNeeds& n) {
  if (n.views.empty() || declared_extent(n) != std::array<double, 4>{0, 0, 1, 1}) return std::nullopt;
  double x = 1, y = 0;
  for (const ViewNeeds& v : n.views) {
    if (!v.viewport) return std::nullopt;
    const auto& r = *v.viewport;
    if (r[0] + r[2] >= 1 - 1e-9) x = std::min(x, r[0]), y = std::max(y, r[1] + r[3]);
  }
  if (x >= 1 || y >= 1 - 1e-9) return std::nullopt;
  for (const ViewNeeds& v : n.views) {
    const auto& r = *v.viewport;
    if (r[0] + r[2] > x + 1e-9 && r[1] + r[3] > y + 1e-9) return std::nullopt;
  }
  return std::array<double, 4>{x, y, 1 - x, 1 - y};
}

// The frame key: in a free corner of the views (free_corner), its entries in
// as few rows as the corner's width allows, when they fit there; else its rows
// across the frame, above the captions.
void plan_frame_key(const FrameNeeds& n, FramePlan& p) {
  if (p.frame_key.empty()) return;
  p.frame_key_px = viz::text_px(viz::TextRole::key, n.height, n.text_scale);
  if (p.frame_key_px < viz::kMinKeyPx) {
    p.notes.push_back("frame key left out: its text would be " + px(p.frame_key_px) + " high, under the " +
                      px(viz::kMinKeyPx) + " a key needs to be read");
    p.frame_key.clear(), p.frame_key_from.clear();
    return;
  }
  const float pad = 0.5f * p.frame_key_px;
  if (const auto c = free_corner(n)) {
    const viz::Box a = views_area(n, p);
    const viz::Box box{static_cast<float>((*c)[0] * n.width), a.y0 + static_cast<float>((*c)[1]) * (a.y1 - a.y0),
                       static_cast<float>(n.width), a.y1};
    const glm::vec2 size = viz::key_rows(p.frame_key, p.frame_key_px, box.x1 - box.x0 - 2 * pad).size;
    if (size.x <= box.x1 - box.x0 - 2 * pad && size.y + 2 * pad <= box.y1 - box.y0) {
      p.frame_key_box = box, p.frame_key_in_corner = true;
      return;
    }
  }
  const glm::vec2 size = viz::key_rows(p.frame_key, p.frame_key_px, static_cast<float>(n.width) - 2 * pad).size;
  float bottom = static_cast<float>(n.height);
  if (p.captions.y1 > p.captions.y0 && p.captions.y0 > 0) bottom = p.captions.y0;
  p.frame_key_box = {0, bottom - std::ceil(size.y + 2 * pad), static_cast<float>(n.width), bottom};
}

// The extent the declared viewports cover together, x0, y0, x1, y1 (the unit square when any view has none).
std::array<double, 4> declared_extent(const FrameNeeds& n) {
  std::array<double, 4> e{1, 1, 0, 0};
  for (const ViewNeeds& v : n.views) {
    if (!v.viewport) return {0, 0, 1, 1};
    const auto& f = *v.viewport;
    e = {std::min(e[0], f[0]), std::min(e[1], f[1]), std::max(e[2], f[0] + f[2]), std::max(e[3], f[1] + f[3])};
  }
  return e[2] > e[0] && e[3] > e[1] ? e : std::array<double, 4>{0, 0, 1, 1};
}

glm::dvec4 view_fractions(const FrameNeeds& n, const viz::Box& area, std::size_t i, int count) {
  const double W = n.width, H = n.height, aw = area.x1 - area.x0, ah = area.y1 - area.y0;
  std::array<double, 4> f;
  if (n.views[i].viewport) {
    // Declared viewports are stretched together to fill the views' area: a
    // band they leave free at its edges (once kept for the captions, which now
    // have their own strip) would stay empty.
    const std::array<double, 4> e = declared_extent(n);
    const auto& d = *n.views[i].viewport;
    const double sx = 1 / (e[2] - e[0]), sy = 1 / (e[3] - e[1]);
    f = {(d[0] - e[0]) * sx, (d[1] - e[1]) * sy, d[2] * sx, d[3] * sy};
  } else {
    const int cols = std::max(1, std::min(n.columns, count)), rows = (count + cols - 1) / cols;
    const int c = static_cast<int>(i) % cols, r = static_cast<int>(i) / cols;
    f = {double(c) / cols, double(r) / rows, 1.0 / cols, 1.0 / rows};
  }
  return {(area.x0 + f[0] * aw) / W, (area.y0 + f[1] * ah) / H, f[2] * aw / W, f[3] * ah / H};
}

// The title strip: the title wrapped to the view, then the overlay lines.
float plan_title(const ViewNeeds& v, int frame_h, double text_scale, float pad, ViewPlan& vp) {
  vp.title_px = viz::text_px(viz::TextRole::view_title, frame_h, text_scale);
  vp.overlay_px = viz::text_px(v.large_overlay ? viz::TextRole::view_title : viz::TextRole::label, frame_h, text_scale);
  float bottom = 0;
  if (!v.title.empty()) {
    vp.title = viz::wrap_text(v.title, vp.title_px, static_cast<float>(vp.width) - 2 * pad);
    vp.title_at = {pad, 0.35f * vp.title_px};
    bottom = vp.title_at.y + static_cast<float>(viz::text_lines(vp.title)) * vp.title_px;
  }
  vp.overlay_y = bottom + (bottom > 0 ? 0.15f : 0.35f) * vp.overlay_px;
  if (v.overlay_lines > 0) bottom = vp.overlay_y + static_cast<float>(v.overlay_lines) * vp.overlay_px;
  return bottom > 0 ? bottom + 0.3f * vp.title_px : pad;
}

// The key strip beside the content (right), else below it, else nowhere (a note says why).
void plan_key(const ViewNeeds& v, std::size_t i, int frame_h, double text_scale, float top, float pad, ViewPlan& vp,
              std::vector<std::string>& notes) {
  const float w = static_cast<float>(vp.width), h = static_cast<float>(vp.height);
  const float side = v.edge_to_edge ? 0.0f : pad;
  vp.content = {side, top, w - side, h - side};
  if (vp.key.empty()) return;
  vp.key_px = viz::text_px(viz::TextRole::key, frame_h, text_scale);
  if (vp.key_px < viz::kMinKeyPx) {
    notes.push_back(view_name(i, v) + ": key left out: its text would be " + px(vp.key_px) +
                    " high, under the " + px(viz::kMinKeyPx) + " a key needs to be read");
    vp.key.clear();
    return;
  }
  const glm::vec2 ks = viz::key_size(vp.key, vp.key_px);
  const float beside_w = w - ks.x - 3 * pad, room_h = h - top - pad;
  if (ks.y <= room_h && beside_w >= kMinContentShare * w) {
    vp.key_at = glm::vec2(w - pad - ks.x, top);
    vp.content.x1 = vp.key_at->x - pad;
    return;
  }
  const float below_h = room_h - ks.y - pad;
  if (ks.x <= w - 2 * pad && below_h >= kMinContentShare * (h - top)) {
    vp.key_at = glm::vec2(pad, h - pad - ks.y);
    vp.content.y1 = vp.key_at->y - pad;
    return;
  }
  vp.key.clear();
  notes.push_back(view_name(i, v) + ": key left out: it is " + px(ks.x) + " × " + px(ks.y) +
                  "; beside the content it would leave " + px(std::max(0.0f, beside_w)) + " of the view's " + px(w) +
                  " width, below it " + px(std::max(0.0f, below_h)) + " of its " + px(h - top) +
                  " height (a key needs the content to keep " + std::to_string(int(kMinContentShare * 100)) + " %)");
}

}  // namespace

std::string view_name(std::size_t i, const std::string& kind, const std::string& title) {
  return "view " + std::to_string(i) + " (" + kind + (title.empty() ? "" : ", '" + title + "'") + ")";
}

FramePlan plan_frame(const FrameNeeds& n) {
  FramePlan p;
  plan_captions(n, p);
  p.frame_key = n.frame_key;
  p.frame_key_from.assign(p.frame_key.size(), {});
  p.frame_key_always = !n.frame_key.empty();
  std::vector<std::vector<viz::KeyEntry>> keys = split_keys(n, p);
  move_wide_keys(n, p, keys);
  plan_frame_key(n, p);
  const viz::Box area = views_area(n, p);
  const int count = static_cast<int>(n.views.size());
  const float pad = 0.5f * viz::text_px(viz::TextRole::key, n.height, n.text_scale);
  for (std::size_t i = 0; i < n.views.size(); ++i) {
    ViewPlan vp;
    vp.key = std::move(keys[i]);
    vp.viewport = view_fractions(n, area, i, count);
    viz::View probe;
    probe.viewport = vp.viewport;
    const PixelRect r = view_rect(probe, static_cast<int>(i), count, 1, n.width, n.height);
    vp.x = r.x, vp.y = r.y, vp.width = r.width, vp.height = r.height;
    const float top = plan_title(n.views[i], n.height, n.text_scale, pad, vp);
    plan_key(n.views[i], i, n.height, n.text_scale, top, pad, vp, p.notes);
    if (vp.content.x1 - vp.content.x0 < 16 || vp.content.y1 - vp.content.y0 < 16)
      p.notes.push_back(view_name(i, n.views[i]) + ": its title and key leave its content " +
                        px(vp.content.x1 - vp.content.x0) + " × " + px(vp.content.y1 - vp.content.y0));
    p.views.push_back(std::move(vp));
  }
  return p;
}

}  // namespace tumble::compose
