#include "viz/text_layout.hpp"

#include <algorithm>
#include <array>
#include <sstream>

#include "viz/captions.hpp"

namespace tumble::viz {

namespace {

// Advances of DejaVu Sans, U+0020..U+007E, in em (hmtx / unitsPerEm 2048),
// read with fontTools from /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf.
constexpr std::array<float, 95> kAscii = {
    0.318f, 0.401f, 0.46f,  0.838f, 0.636f, 0.95f,  0.78f,  0.275f, 0.39f,  0.39f,  0.5f,   0.838f, 0.318f, 0.361f,
    0.318f, 0.337f, 0.636f, 0.636f, 0.636f, 0.636f, 0.636f, 0.636f, 0.636f, 0.636f, 0.636f, 0.636f, 0.337f, 0.337f,
    0.838f, 0.838f, 0.838f, 0.531f, 1.0f,   0.684f, 0.686f, 0.698f, 0.77f,  0.632f, 0.575f, 0.775f, 0.752f, 0.295f,
    0.295f, 0.656f, 0.557f, 0.863f, 0.748f, 0.787f, 0.603f, 0.787f, 0.695f, 0.635f, 0.611f, 0.732f, 0.684f, 0.989f,
    0.685f, 0.611f, 0.685f, 0.39f,  0.337f, 0.39f,  0.838f, 0.5f,   0.5f,   0.613f, 0.635f, 0.55f,  0.635f, 0.615f,
    0.352f, 0.635f, 0.634f, 0.278f, 0.278f, 0.579f, 0.278f, 0.974f, 0.634f, 0.612f, 0.635f, 0.635f, 0.411f, 0.521f,
    0.392f, 0.634f, 0.592f, 0.818f, 0.592f, 0.592f, 0.525f, 0.636f, 0.337f, 0.636f, 0.838f};

// Advance of code point `c`, em: sub/superscripts are narrow, other symbols
// (Greek, arrows, operators, ×, ½) about 0.84 em in DejaVu Sans.
float advance(char32_t c) {
  if (c >= 0x20 && c < 0x7F) return kAscii[c - 0x20];
  if (c >= 0x2070 && c <= 0x209F) return 0.401f;
  if (c == 0xB7 || c == 0x2009) return 0.318f;
  if (c == 0x25A0) return 0.945f;
  return 0.84f;
}

char32_t decode(std::string_view s, std::size_t& i) {
  const auto b = static_cast<unsigned char>(s[i++]);
  if (b < 0x80) return b;
  const int extra = b >= 0xF0 ? 3 : b >= 0xE0 ? 2 : b >= 0xC0 ? 1 : 0;
  char32_t c = b & (0x3F >> extra);
  for (int k = 0; k < extra && i < s.size(); ++k) c = (c << 6) | (static_cast<unsigned char>(s[i++]) & 0x3F);
  return c;
}

float line_width(std::string_view line, float size_px) {
  float w = 0;
  for (std::size_t i = 0; i < line.size();) w += advance(decode(line, i));
  return w * size_px;
}

}  // namespace

float text_px(TextRole role, int frame_h) {
  // Fractions of the frame height; the smallest (ticks) is 2.2 %, legible at 360p.
  float f = 0;
  switch (role) {
    case TextRole::title: f = 0.070f; break;
    case TextRole::subtitle: f = 0.040f; break;
    case TextRole::caption: f = 0.034f; break;
    case TextRole::view_title: f = 0.029f; break;
    case TextRole::key: f = 0.024f; break;
    case TextRole::label: f = 0.026f; break;
    case TextRole::tick: f = 0.022f; break;
  }
  return f * static_cast<float>(frame_h);
}

float text_width(std::string_view text, float size_px) {
  float widest = 0;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = text.find('\n', start);
    widest = std::max(widest, line_width(text.substr(start, end - start), size_px));
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
  return widest;
}

int text_lines(std::string_view text) { return 1 + static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

std::string wrap_text(std::string_view text, float size_px, float max_width_px) {
  std::string out;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = text.find('\n', start);
    std::istringstream words{std::string(text.substr(start, end - start))};
    std::string word, line;
    while (words >> word) {
      const std::string longer = line.empty() ? word : line + " " + word;
      if (!line.empty() && line_width(longer, size_px) > max_width_px) {
        out += line + "\n";
        line = word;
      } else {
        line = longer;
      }
    }
    out += line;
    if (end == std::string_view::npos) break;
    out += "\n";
    start = end + 1;
  }
  return out;
}

Box text_box(const TextItem& t) {
  const float w = text_width(t.text, t.size_px), h = static_cast<float>(text_lines(t.text)) * t.size_px;
  return {t.position_px.x, t.position_px.y, t.position_px.x + w, t.position_px.y + h};
}

}  // namespace tumble::viz

namespace tumble::viz {

float add_view_title(View& view, const std::string& title, float width_px, int frame_h) {
  if (title.empty()) return 0;
  const float size = text_px(TextRole::view_title, frame_h), pad = 0.5f * size;
  TextItem t{wrap_text(title, size, width_px - 2 * pad), {pad, 0.35f * size}, size, color_of(Meaning::ink, 0.95f)};
  t.name = "view_title";
  const float bottom = text_box(t).y1 + 0.3f * size;
  view.texts.push_back(std::move(t));
  return bottom;
}

}  // namespace tumble::viz
