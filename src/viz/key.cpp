#include "viz/key.hpp"

#include <algorithm>

#include "viz/scene_view.hpp"

namespace tumble::viz {

namespace {

const char* swatch_glyphs(Swatch s) {
  switch (s) {
    case Swatch::line: return "\u2501\u2501";  // ━━
    case Swatch::dot: return "\u25CF";         // ●
    case Swatch::block: return "\u25A0";       // ■
  }
  return "?";
}

constexpr float kLine = 1.3f;   // line pitch, in sizes
constexpr float kPad = 0.45f;   // backdrop margin, in sizes
constexpr float kGap = 0.4f;    // between swatch and text, in sizes

float swatch_width(const KeyEntry& e, float size_px) {
  return static_cast<float>(e.colors.size()) * text_width(swatch_glyphs(e.swatch), size_px);
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
    out.push_back({Swatch::line, {kAxisColors[0], kAxisColors[1], kAxisColors[2]},
                   d.trail_seconds > 0 ? "e\u2081 e\u2082 e\u2083 (I\u2081 < I\u2082 < I\u2083), tip trails"
                                       : "e\u2081 e\u2082 e\u2083: I\u2081 < I\u2082 < I\u2083"});
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
    const float step = text_width(swatch_glyphs(entries[i].swatch), size_px);
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

Box add_key_bottom_right(View& view, const std::vector<KeyEntry>& entries, float width_px, float height_px,
                         float top_px, float size_px) {
  const glm::vec2 size = key_size(entries, size_px);
  const float margin = 0.5f * size_px;
  return add_key(view, entries,
                 {std::max(margin, width_px - size.x - margin), std::max(top_px, height_px - size.y - margin)}, size_px);
}

Box add_key_clear(View& view, const std::vector<KeyEntry>& entries, float width_px, float height_px, float top_px,
                  float size_px, const std::vector<Box>& avoid) {
  const glm::vec2 size = key_size(entries, size_px);
  const float m = 0.5f * size_px;
  const float right = std::max(m, width_px - size.x - m), bottom = std::max(top_px + m, height_px - size.y - m);
  const glm::vec2 corners[] = {{right, bottom}, {m, bottom}, {right, top_px + m}};
  glm::vec2 best = corners[0];
  float least = 1e30f;
  for (const glm::vec2& c : corners) {
    const Box b{c.x, c.y, c.x + size.x, c.y + size.y};
    float covered = 0;
    for (const Box& o : avoid) {
      const float w = std::min(b.x1, o.x1) - std::max(b.x0, o.x0), h = std::min(b.y1, o.y1) - std::max(b.y0, o.y0);
      if (w > 0 && h > 0) covered += w * h;
    }
    if (covered < least) least = covered, best = c;
    if (covered == 0) break;
  }
  return add_key(view, entries, best, size_px);
}

}  // namespace tumble::viz
