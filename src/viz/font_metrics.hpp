// DejaVu Sans' horizontal metrics (the renderer's font, render::FontAtlas), per
// code point the atlas holds, in units of the text's size: the renderer scales
// a glyph so that ascent − descent is the size in px (stb_truetype's
// ScaleForPixelHeight), so an advance of 0.54 is 0.54 × size_px on screen.
// GL-free: the layout measures text exactly as it is drawn. The table
// (font_metrics.inc) is written from the font by the font test
// (TUMBLE_UPDATE_FONT_METRICS=1 ctest -R FontMetrics), which also holds it equal.
#pragma once

#include <span>

namespace tumble::viz {

struct GlyphMetrics {
  char32_t code;
  float advance;  ///< pen advance, sizes
  float ink_x0;   ///< left edge of the glyph's outline from the pen, sizes (0, 0 for a blank)
  float ink_x1;   ///< right edge, sizes
};

/// Every glyph of the atlas, by code point.
std::span<const GlyphMetrics> glyph_table();

/// The metrics of `c`; a code point the atlas lacks is drawn (and measured) as '?'.
const GlyphMetrics& glyph_metrics(char32_t c);

}  // namespace tumble::viz
