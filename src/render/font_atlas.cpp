#define STB_TRUETYPE_IMPLEMENTATION
#define STBTT_STATIC
#include <stb/stb_truetype.h>

#include "render/font_atlas.hpp"

#include "base/input_file.hpp"
#include "render/font_check.hpp"
#include "render/resource_dir.hpp"

#include <algorithm>
#include <array>
#include <iterator>
#include <stdexcept>

namespace tumble::render {
namespace {

constexpr std::size_t kMaxFontBytes = std::size_t(64) << 20;  // DejaVu Sans is 0.7 MB
constexpr const char* kFontPackage = " (tumble reads DejaVu Sans, from the Debian package fonts-dejavu-core)";

struct Range {
  char32_t first;
  int count;
};
// ASCII, Latin-1 (×, ½, ±, ·), Greek, general punctuation (dashes, bullets,
// ellipsis, primes), super- and subscripts (ω₁, I₂, x²), arrows (→), the
// common math operators (∂ ∇ − √ ∝ ∞ ∠ ∥ ∫ ≈ ≠ ≡ ≤ ≥ ⊥ ⋅) and the key's
// swatches (━ █ ■ ●). DejaVu Sans has them all; U+2588 (█) also gives the
// solid texel backdrops are drawn with.
constexpr std::array<Range, 14> kRanges = {{{0x20, 95},
                                            {0xA0, 96},
                                            {0x391, 57},
                                            {0x2010, 24},
                                            {0x2030, 8},
                                            {0x2070, 48},
                                            {0x2190, 10},
                                            {0x2200, 48},
                                            {0x2248, 1},
                                            {0x2260, 6},
                                            {0x22A5, 1},
                                            {0x22C5, 1},
                                            {0x2501, 1},
                                            {0x2588, 1}}};
// Padding between packed glyphs (bake px), so mipmap levels do not bleed; a
// quad reaches kQuadMarginBakePx of it (at most one screen pixel).
constexpr int kPaddingBakePx = 8;
constexpr float kQuadMarginBakePx = 4;

constexpr std::array<Range, 2> kShapes = {{{0x25A0, 1}, {0x25CF, 1}}};

// Minimal UTF-8 decoder; malformed bytes come out as '?'.
char32_t next_code_point(std::string_view s, std::size_t& i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char b0 = byte(i++);
  if (b0 < 0x80) return b0;
  const int extra = b0 >= 0xF0 ? 3 : b0 >= 0xE0 ? 2 : b0 >= 0xC0 ? 1 : -1;
  if (extra < 0 || i + extra > s.size()) return U'?';
  char32_t c = b0 & (0x3F >> extra);
  for (int k = 0; k < extra; ++k) {
    if ((byte(i) & 0xC0) != 0x80) return U'?';
    c = (c << 6) | (byte(i++) & 0x3F);
  }
  return c;
}

}  // namespace

FontAtlas::FontAtlas(const std::filesystem::path& ttf, float bake_px) : bake_px_(bake_px) {
  std::string bytes;
  try {
    bytes = read_input_file(ttf, kMaxFontBytes, "font");
  } catch (const std::exception& e) {
    throw ResourceError(std::string(e.what()) + kFontPackage);
  }
  if (const std::string why = truetype_problem(bytes); !why.empty())
    throw ResourceError(ttf.string() + ": damaged font: " + why + kFontPackage);
  const std::vector<unsigned char> data(bytes.begin(), bytes.end());

  stbtt_fontinfo info;
  if (!stbtt_InitFont(&info, data.data(), stbtt_GetFontOffsetForIndex(data.data(), 0))) {
    throw ResourceError(ttf.string() + ": not a usable TrueType font" + kFontPackage);
  }
  int ascent = 0, descent = 0, gap = 0;
  stbtt_GetFontVMetrics(&info, &ascent, &descent, &gap);
  const float scale = stbtt_ScaleForPixelHeight(&info, bake_px);
  texel_ = {1.0f / static_cast<float>(width_), 1.0f / static_cast<float>(height_)};
  ascent_px_ = ascent * scale;
  line_px_ = (ascent - descent + gap) * scale;

  // Generous padding keeps glyphs from bleeding into each other in the
  // mipmap levels used when text is drawn much smaller than the bake size.
  pixels_.assign(static_cast<std::size_t>(width_) * height_, 0);
  stbtt_pack_context pack;
  if (!stbtt_PackBegin(&pack, pixels_.data(), width_, height_, 0, kPaddingBakePx, nullptr)) {
    throw std::runtime_error("stbtt_PackBegin failed");
  }
  bool ok = true;
  std::vector<Range> ranges(kRanges.begin(), kRanges.end());
  ranges.insert(ranges.end(), kShapes.begin(), kShapes.end());
  for (const Range& r : ranges) {
    std::vector<stbtt_packedchar> packed(r.count);
    ok = ok && stbtt_PackFontRange(&pack, data.data(), 0, bake_px, static_cast<int>(r.first),
                                   r.count, packed.data());
    for (int k = 0; ok && k < r.count; ++k) {
      const stbtt_packedchar& p = packed[k];
      glyphs_.push_back({r.first + k,
                         Glyph{p.xoff, p.yoff, p.xoff2, p.yoff2, p.x0 / float(width_),
                               p.y0 / float(height_), p.x1 / float(width_),
                               p.y1 / float(height_), p.xadvance}});
    }
  }
  stbtt_PackEnd(&pack);
  // DejaVu Sans fills about half the atlas; only a damaged font's glyph boxes overflow it.
  if (!ok) throw ResourceError(ttf.string() + ": damaged font: its glyphs do not fit the atlas (boxes too large)" + kFontPackage);
  std::sort(glyphs_.begin(), glyphs_.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  // The middle of the full block: coverage 1 at every mipmap level text uses.
  const Glyph* block = find(U'\u2588');
  solid_uv_ = {0.5f * (block->u0 + block->u1), 0.5f * (block->v0 + block->v1)};
}

void FontAtlas::rect(glm::vec4 box_px, glm::vec4 color, std::vector<TextVertex>& out) const {
  const TextVertex a{{box_px.x, box_px.y}, solid_uv_, color}, b{{box_px.z, box_px.y}, solid_uv_, color},
      d{{box_px.x, box_px.w}, solid_uv_, color}, e{{box_px.z, box_px.w}, solid_uv_, color};
  out.insert(out.end(), {a, b, e, a, e, d});
}

const FontAtlas::Glyph* FontAtlas::find(char32_t c) const {
  auto it = std::lower_bound(glyphs_.begin(), glyphs_.end(), c,
                             [](const auto& g, char32_t v) { return g.first < v; });
  if (it != glyphs_.end() && it->first == c) return &it->second;
  return c == U'?' ? nullptr : find(U'?');
}

void FontAtlas::layout(std::string_view text, glm::vec2 top_left_px, float size_px,
                       glm::vec4 color, std::vector<TextVertex>& out) const {
  const float s = size_px / bake_px_;
  // Each quad reaches a pixel into its glyph's padding: a stem thinner than a
  // pixel (l, i, I at 8 px) otherwise covers no pixel centre and vanishes,
  // while the mipmap has spread its coverage into that margin.
  const float margin = std::min(kQuadMarginBakePx, 1.0f / s);  // bake px
  glm::vec2 pen(top_left_px.x, top_left_px.y + ascent_px_ * s);
  for (std::size_t i = 0; i < text.size();) {
    const char32_t c = next_code_point(text, i);
    if (c == U'\n') {
      pen = {top_left_px.x, pen.y + line_px_ * s};
      continue;
    }
    const Glyph* g = find(c);
    if (g == nullptr) continue;
    const glm::vec2 p0 = pen + (glm::vec2(g->x0, g->y0) - margin) * s;
    const glm::vec2 p1 = pen + (glm::vec2(g->x1, g->y1) + margin) * s;
    const glm::vec2 uv0 = glm::vec2(g->u0, g->v0) - margin * texel_;
    const glm::vec2 uv1 = glm::vec2(g->u1, g->v1) + margin * texel_;
    const TextVertex a{p0, uv0, color}, b{{p1.x, p0.y}, {uv1.x, uv0.y}, color}, d{{p0.x, p1.y}, {uv0.x, uv1.y}, color},
        e{p1, uv1, color};
    out.insert(out.end(), {a, b, e, a, e, d});
    pen.x += g->advance * s;
  }
}

std::vector<char32_t> FontAtlas::code_points() const {
  std::vector<char32_t> out;
  for (const auto& g : glyphs_) out.push_back(g.first);
  return out;
}

glm::vec2 FontAtlas::measure(std::string_view text, float size_px) const {
  const float s = size_px / bake_px_;
  float line = 0, widest = 0;
  int lines = 1;
  for (std::size_t i = 0; i < text.size();) {
    const char32_t c = next_code_point(text, i);
    if (c == U'\n') {
      widest = std::max(widest, line);
      line = 0;
      ++lines;
    } else if (const Glyph* g = find(c)) {
      line += g->advance * s;
    }
  }
  return {std::max(widest, line), lines * line_px_ * s};
}

}  // namespace tumble::render
