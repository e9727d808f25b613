#include "viz/key.hpp"

#include <algorithm>
#include <cmath>

#include "viz/captions.hpp"
#include "viz/scene_view.hpp"

namespace tumble::viz {

namespace {

const char* swatch_glyphs(Swatch s) {
  switch (s) {
    case Swatch::line:
    case Swatch::trail: return "\u2501";       // ━
    case Swatch::dot: return "\u25CF";         // ●
    case Swatch::block: return "\u25A0";       // ■
    case Swatch::arrow: return "\u2192";       // →
  }
  return "?";
}

constexpr float kLine = 1.3f;   // line pitch, in sizes
constexpr float kPad = 0.45f;   // backdrop margin, in sizes
constexpr float kGap = 0.4f;    // between swatch and text, in sizes

// One swatch per colour, a small gap apart so that three axis colours read as
// three marks; a trail's colours touch (a hair of overlap), one solid line.
float swatch_step(Swatch s, float size_px) {
  return text_width(swatch_glyphs(s), size_px) + (s == Swatch::trail ? -0.02f : 0.15f) * size_px;
}

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

std::vector<KeyEntry> bodies_key(const DrawOptions& d, const std::vector<std::pair<std::string, Color>>& bodies,
                                 bool arrows) {
  std::vector<KeyEntry> out;
  // The arrows carry their names at their tips; the key says what the names mean, briefly.
  const std::vector<Color> axes{kAxisColors[0], kAxisColors[1], kAxisColors[2]};
  const Swatch arrow = arrows ? Swatch::arrow : Swatch::line;
  if (d.axes) out.push_back({arrow, axes, "e\u2081 e\u2082 e\u2083: I\u2081 < I\u2082 < I\u2083"});
  static const char* const kTrailOf[3] = {"trail of e\u2081's tip", "trail of e\u2082's tip", "trail of e\u2083's tip"};
  std::vector<Color> trailed;  // the trails, drawn fading
  for (std::size_t i = 0; i < 3; ++i)
    if (d.trail_axes[i]) trailed.push_back(Color(glm::vec3(kAxisColors[i]), arrows ? 0.4f : kAxisColors[i].a));
  if (d.axes && d.trail_seconds > 0 && !trailed.empty()) {
    const auto one = std::find(d.trail_axes.begin(), d.trail_axes.end(), true) - d.trail_axes.begin();
    out.push_back({Swatch::trail, trailed, trailed.size() == 1 ? kTrailOf[one] : "trails of their tips"});
  }
  if (d.angular_momentum) out.push_back({arrow, {color_of(Meaning::L)}, "L: angular momentum (direction)"});
  if (d.omega) out.push_back({arrow, {color_of(Meaning::omega)}, "\u03c9: angular velocity (direction)"});
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

namespace {

constexpr float kEntryGap = 1.6f;  // between entries in a row, in sizes

float entry_width(const KeyEntry& e, float size_px) {
  return swatch_width(e, size_px) + kGap * size_px + text_width(e.text, size_px);
}

// The swatches and text of one entry from pen x, line top y.
void add_entry(std::vector<TextItem>& texts, const KeyEntry& e, float x, float y, float size_px) {
  const float step = swatch_step(e.swatch, size_px);
  for (std::size_t c = 0; c < e.colors.size(); ++c) {
    TextItem swatch{swatch_glyphs(e.swatch), {x + step * static_cast<float>(c), y}, size_px, e.colors[c], "key_swatch"};
    swatch.key = true;
    texts.push_back(std::move(swatch));
  }
  TextItem text{e.text, {x + swatch_width(e, size_px) + kGap * size_px, y}, size_px, color_of(Meaning::ink), "key"};
  text.key = true;
  texts.push_back(std::move(text));
}

}  // namespace

KeyRows key_rows(const std::vector<KeyEntry>& entries, float size_px, float max_width_px) {
  KeyRows k;
  const float room = max_width_px - 2 * kPad * size_px;
  float row_w = 0, widest = 0;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const float w = entry_width(entries[i], size_px);
    if (k.rows.empty() || (row_w + kEntryGap * size_px + w > room && !k.rows.back().empty())) {
      k.rows.emplace_back();
      row_w = -kEntryGap * size_px;
    }
    row_w += kEntryGap * size_px + w;
    widest = std::max(widest, row_w);
    k.rows.back().push_back(i);
  }
  const float n = static_cast<float>(k.rows.size());
  if (!k.rows.empty()) k.size = {widest + 2 * kPad * size_px, ((n - 1) * kLine + 1 + 2 * kPad) * size_px};
  return k;
}

Box add_key_row(std::vector<TextItem>& texts, const std::vector<KeyEntry>& entries, float centre_x, float top,
                float size_px, float max_width_px) {
  const KeyRows k = key_rows(entries, size_px, max_width_px);
  const Box box{centre_x - 0.5f * k.size.x, top, centre_x + 0.5f * k.size.x, top + k.size.y};
  if (k.rows.empty()) return box;
  const std::size_t first = texts.size();
  for (std::size_t r = 0; r < k.rows.size(); ++r) {
    float w = -kEntryGap * size_px;
    for (std::size_t i : k.rows[r]) w += kEntryGap * size_px + entry_width(entries[i], size_px);
    float x = centre_x - 0.5f * w;
    const float y = top + (kPad + kLine * static_cast<float>(r)) * size_px;
    for (std::size_t i : k.rows[r]) {
      add_entry(texts, entries[i], x, y, size_px);
      x += entry_width(entries[i], size_px) + kEntryGap * size_px;
    }
  }
  // The whole key's backdrop, drawn before its first glyph.
  texts[first].backdrop = {0.99f, 0.99f, 1.0f, 0.85f};
  texts[first].backdrop_px = {box.x0, box.y0, box.x1, box.y1};
  return box;
}

bool same_entry(const KeyEntry& a, const KeyEntry& b) {
  return a.swatch == b.swatch && a.colors == b.colors && a.text == b.text;
}

}  // namespace tumble::viz
