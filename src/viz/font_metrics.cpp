#include "viz/font_metrics.hpp"

#include <algorithm>
#include <iterator>

namespace tumble::viz {

namespace {

constexpr GlyphMetrics kGlyphs[] = {
#include "viz/font_metrics.inc"
};

}  // namespace

std::span<const GlyphMetrics> glyph_table() { return kGlyphs; }

const GlyphMetrics& glyph_metrics(char32_t c) {
  const auto* it = std::lower_bound(std::begin(kGlyphs), std::end(kGlyphs), c,
                                    [](const GlyphMetrics& g, char32_t v) { return g.code < v; });
  if (it != std::end(kGlyphs) && it->code == c) return *it;
  return c == U'?' ? kGlyphs[0] : glyph_metrics(U'?');
}

}  // namespace tumble::viz
