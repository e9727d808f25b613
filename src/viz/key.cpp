#include "viz/key.hpp"

#include <algorithm>
#include <cmath>

#include "viz/captions.hpp"
#include "viz/scene_view.hpp"

namespace tumble::viz {

namespace {

const char* swatch_glyphs(Swatch s) {
  switch (s) {
    case Swatch::line: return "\u2501";        // ━
    case Swatch::dot: return "\u25CF";         // ●
    case Swatch::block: return "\u25A0";       // ■
  }
  return "?";
}

constexpr float kLine = 1.3f;   // line pitch, in sizes
constexpr float kPad = 0.45f;   // backdrop margin, in sizes
constexpr float kGap = 0.4f;    // between swatch and text, in sizes

// One swatch per colour, a small gap apart so that three axis colours read as three dashes.
float swatch_step(Swatch s, float size_px) { return text_width(swatch_glyphs(s), size_px) + 0.15f * size_px; }

float swatch_width(const KeyEntry& e, float size_px) {
  return static_cast<float>(e.colors.size()) * swatch_step(e.swatch, size_px);
}

float swatch_column(const std::vector<KeyEntry>& entries, float size_px) {
  float w = 0;
  for (const KeyEntry& e : entries) w = std::max(w, swatch_width(e, size_px));
  return w;
}

}  // namespace

KeyEntry key_entry(Meaning m, std::string text) {
  const Swatch s = m == Meaning::momentum_point ? Swatch::dot : Swatch::line;
  return {s, {color_of(m)}, std::move(text)};
}

std::vector<KeyEntry> bodies_key(const DrawOptions& d, const std::vector<std::pair<std::string, Color>>& bodies) {
  std::vector<KeyEntry> out;
  if (d.axes)
    out.push_back({Swatch::line, {kAxisColors[0], kAxisColors[1], kAxisColors[2]}, "e\u2081 e\u2082 e\u2083: I\u2081 < I\u2082 < I\u2083"});
  if (d.angular_momentum) out.push_back(key_entry(Meaning::L, "L, fixed in space"));
  if (d.omega) out.push_back(key_entry(Meaning::omega, "\u03c9, angular velocity"));
  for (const auto& [name, color] : bodies) out.push_back({Swatch::block, {Color(glm::vec3(color), 1.0f)}, name});
  return out;
}

glm::vec2 key_size(const std::vector<KeyEntry>& entries, float size_px) {
  float text = 0;
  for (const KeyEntry& e : entries) text = std::max(text, text_width(e.text, size_px));
  const float n = static_cast<float>(entries.size());
  return {swatch_column(entries, size_px) + (kGap + 2 * kPad) * size_px + text,
          ((n - 1) * kLine + 1 + 2 * kPad) * size_px};
}

Box add_key(View& view, const std::vector<KeyEntry>& entries, glm::vec2 top_left, float size_px) {
  if (entries.empty()) return {top_left.x, top_left.y, top_left.x, top_left.y};
  const glm::vec2 size = key_size(entries, size_px);
  const Box box{top_left.x, top_left.y, top_left.x + size.x, top_left.y + size.y};
  const float x_swatch = top_left.x + kPad * size_px;
  const float x_text = x_swatch + swatch_column(entries, size_px) + kGap * size_px;
  const Color ink = color_of(Meaning::ink);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const float y = top_left.y + (kPad + kLine * static_cast<float>(i)) * size_px;
    const float step = swatch_step(entries[i].swatch, size_px);
    for (std::size_t c = 0; c < entries[i].colors.size(); ++c) {
      TextItem swatch{swatch_glyphs(entries[i].swatch), {x_swatch + step * static_cast<float>(c), y}, size_px,
                      entries[i].colors[c]};
      swatch.name = "key_swatch";
      swatch.key = true;
      if (i == 0 && c == 0) {  // the whole key's backdrop, drawn before its first glyph
        swatch.backdrop = {0.99f, 0.99f, 1.0f, 0.85f};
        swatch.backdrop_px = {box.x0, box.y0, box.x1, box.y1};
      }
      view.texts.push_back(std::move(swatch));
    }
    TextItem text{entries[i].text, {x_text, y}, size_px, ink};
    text.name = "key";
    text.key = true;
    view.texts.push_back(std::move(text));
  }
  return box;
}

Box add_key_top_right(View& view, const std::vector<KeyEntry>& entries, float width_px, float top_px, float size_px) {
  const glm::vec2 size = key_size(entries, size_px);
  const float margin = 0.5f * size_px;
  return add_key(view, entries, {std::max(margin, width_px - size.x - margin), top_px + margin}, size_px);
}

void keep_clear(const View& view, float w, float h, std::vector<Box>& out, std::vector<Box>& texts) {
  auto add_points = [&](const std::vector<glm::dvec3>& pts) {
    if (const auto b = screen_box(view.camera, w, h, pts, 1.0f)) out.push_back(*b);
  };
  for (const BoxItem& b : view.boxes) add_points(box_corners(b));
  const glm::dvec3 up = glm::normalize(view.camera.up);
  const glm::dvec3 right = glm::normalize(glm::cross(view.camera.target - view.camera.position, up));
  for (const PointItem& p : view.points)
    if (!p.name.empty() || p.radius >= 0.5) {  // named, or the momentum sphere's ball
      const double r = 1.04 * p.radius;        // a perspective silhouette is a little wider
      add_points({p.position + r * up, p.position - r * up, p.position + r * right, p.position - r * right});
    }
  for (const SurfaceItem& s : view.surfaces) {
    if (s.name.empty() || !s.mesh) continue;
    std::vector<glm::dvec3> pts;
    for (std::size_t i = 0; i < s.mesh->positions.size(); i += 3)
      pts.push_back(glm::dvec3(s.model * glm::dvec4(glm::dvec3(s.mesh->positions[i]), 1.0)));
    add_points(pts);
  }
  for (const PolylineItem& l : view.polylines)
    if (l.name == "polhode" || l.name == "herpolhode" || l.name == "momentum_path") add_points(l.points);
  for (const TextItem& t : view.texts)
    if (!t.key && !is_label(t)) texts.push_back(text_box(t));
}

std::optional<KeySpot> find_key_spot(glm::vec2 size, float w, float h, float top, float m, const std::vector<Box>& fixed,
                                     const std::vector<Box>& moving, float shift_room) {
  const float right = w - size.x - m, bottom = h - size.y - m;
  if (right < m || bottom < top + m) return std::nullopt;
  const glm::vec2 corners[] = {{right, bottom}, {m, bottom}, {right, top + m}, {m, top + m}};
  for (const glm::vec2& c : corners) {
    const Box b{c.x, c.y, c.x + size.x, c.y + size.y};
    // Content moves away from the key (right of a key on the left) by half the
    // key at most, and no further than its room on the other side.
    float room = std::max(0.0f, shift_room);
    for (const Box& o : moving) room = std::min(room, c.x < 0.5f * w ? w - m - o.x1 : o.x0 - m);
    const float shift = (c.x < 0.5f * w ? 1.0f : -1.0f) * std::clamp(0.5f * size.x, 0.0f, std::max(0.0f, room));
    const auto hit = [&](const Box& o, float dx) { return b.overlaps({o.x0 + dx, o.y0, o.x1 + dx, o.y1}); };
    if (std::any_of(fixed.begin(), fixed.end(), [&](const Box& o) { return hit(o, 0); })) continue;
    if (std::any_of(moving.begin(), moving.end(), [&](const Box& o) { return hit(o, shift); })) continue;
    return KeySpot{c, shift};
  }
  return std::nullopt;
}

void shift_content(View& view, float shift_px, float height_px) {
  const glm::dvec3 eye = view.camera.position - view.camera.target;
  const double world_per_px = 2 * std::tan(glm::radians(view.camera.fov_y_deg) / 2) * glm::length(eye) / height_px;
  const glm::dvec3 right = glm::normalize(glm::cross(view_up(view.camera), glm::normalize(eye)));
  const glm::dvec3 d = static_cast<double>(shift_px) * world_per_px * right;
  view.camera.target -= d;
  view.camera.position -= d;
}

void merge_entries(std::vector<KeyEntry>& a, const std::vector<KeyEntry>& b) {
  for (const KeyEntry& e : b)
    if (std::none_of(a.begin(), a.end(), [&](const KeyEntry& x) { return x.text == e.text && x.colors == e.colors; }))
      a.push_back(e);
}

}  // namespace tumble::viz
