#include "viz/text_layout.hpp"

#include <algorithm>
#include <array>

#include "viz/captions.hpp"
#include "viz/font_metrics.hpp"

namespace tumble::viz {

namespace {

char32_t decode(std::string_view s, std::size_t& i) {
  const auto b = static_cast<unsigned char>(s[i++]);
  if (b < 0x80) return b;
  const int extra = b >= 0xF0 ? 3 : b >= 0xE0 ? 2 : b >= 0xC0 ? 1 : 0;
  char32_t c = b & (0x3F >> extra);
  for (int k = 0; k < extra && i < s.size(); ++k) c = (c << 6) | (static_cast<unsigned char>(s[i++]) & 0x3F);
  return c;
}

// The ink of one line: from the left edge of its first outline to the right
// edge of its last, from the pen's start, px (a blank line: 0, 0).
InkSpan line_ink(std::string_view line, float size_px) {
  float pen = 0, x0 = 1e30f, x1 = -1e30f;
  for (std::size_t i = 0; i < line.size();) {
    const GlyphMetrics& g = glyph_metrics(decode(line, i));
    if (g.ink_x1 > g.ink_x0) x0 = std::min(x0, pen + g.ink_x0), x1 = std::max(x1, pen + g.ink_x1);
    pen += g.advance;
  }
  return x0 > x1 ? InkSpan{} : InkSpan{x0 * size_px, x1 * size_px};
}

float line_width(std::string_view line, float size_px) { return line_ink(line, size_px).width(); }

// Where the spaces before the word at `i` of `para` start.
std::size_t line_gap_start(std::string_view para, std::size_t i) {
  while (i > 0 && para[i - 1] == ' ') --i;
  return i;
}

}  // namespace

float text_px(TextRole role, int frame_h, double scale) {
  // Fractions of the frame height, sized for a lecture hall: captions 4.4 %
  // (24 px at 540p), nothing under 3 % (keys, ticks, labels).
  float f = 0;
  switch (role) {
    case TextRole::title: f = 0.075f; break;
    case TextRole::subtitle: f = 0.046f; break;
    case TextRole::caption: f = 0.044f; break;
    case TextRole::view_title: f = 0.034f; break;
    case TextRole::key: f = 0.031f; break;
    case TextRole::label: f = 0.033f; break;
    case TextRole::tick: f = 0.030f; break;
    case TextRole::badge: f = 0.036f; break;
  }
  const bool hall = role == TextRole::title || role == TextRole::subtitle || role == TextRole::caption;
  return f * static_cast<float>(frame_h) * (hall ? 1.0f : static_cast<float>(scale));
}

InkSpan text_ink(std::string_view text, float size_px) {
  InkSpan all{1e30f, -1e30f};
  std::size_t start = 0;
  while (true) {
    const std::size_t end = text.find('\n', start);
    const InkSpan line = line_ink(text.substr(start, end - start), size_px);
    if (line.width() > 0) all = {std::min(all.x0, line.x0), std::max(all.x1, line.x1)};
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
  return all.x0 > all.x1 ? InkSpan{} : all;
}

float text_width(std::string_view text, float size_px) { return text_ink(text, size_px).width(); }

float centred_x(std::string_view text, float size_px, float centre_px) {
  const InkSpan ink = text_ink(text, size_px);
  return centre_px - 0.5f * (ink.x0 + ink.x1);
}

float right_aligned_x(std::string_view text, float size_px, float right_px) {
  return right_px - text_ink(text, size_px).x1;
}

int text_lines(std::string_view text) { return 1 + static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

std::string wrap_text(std::string_view text, float size_px, float max_width_px) {
  std::string out;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = text.find('\n', start);
    const std::string_view para = text.substr(start, end == std::string_view::npos ? end : end - start);
    std::string line;
    // Words keep the spaces written between them ("red = I1   green = I2"); a break drops them.
    for (std::size_t i = para.find_first_not_of(' '); i != std::string_view::npos;) {
      const std::size_t word_end = std::min(para.find(' ', i), para.size());
      const std::size_t gap = i - line_gap_start(para, i);
      const std::string word(para.substr(i, word_end - i));
      const std::string longer = line.empty() ? word : line + std::string(gap, ' ') + word;
      if (!line.empty() && line_width(longer, size_px) > max_width_px) {
        out += line + "\n";
        line = word;
      } else {
        line = longer;
      }
      i = para.find_first_not_of(' ', word_end);
    }
    out += line;
    if (end == std::string_view::npos) break;
    out += "\n";
    start = end + 1;
  }
  return out;
}

Box text_box(const TextItem& t) {
  const InkSpan ink = text_ink(t.text, t.size_px);
  const float h = static_cast<float>(text_lines(t.text)) * t.size_px;
  return {t.position_px.x + ink.x0, t.position_px.y, t.position_px.x + ink.x1, t.position_px.y + h};
}

}  // namespace tumble::viz
