#define STB_TRUETYPE_IMPLEMENTATION
#define STBTT_STATIC
#include <stb/stb_truetype.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "render/font_atlas.hpp"
#include "render/resource_dir.hpp"
#include "viz/font_metrics.hpp"

namespace tumble::render {
namespace {

TEST(ResourceDir, FindsShaders) {
  const auto dir = find_resource_dir();
  EXPECT_TRUE(std::filesystem::exists(dir / "shaders" / "mesh.vert")) << dir;
}

TEST(FontAtlas, LaysOutTextInPixels) {
  const FontAtlas atlas(find_font_file(find_resource_dir()));
  std::vector<TextVertex> quads;
  atlas.layout("Hi ω", {10, 20}, 16, {0, 0, 0, 1}, quads);
  EXPECT_EQ(quads.size(), 4u * 6u);  // the space gets an empty quad too
  for (const TextVertex& v : quads) {
    EXPECT_GE(v.position_px.x, 9.0f);
    EXPECT_GE(v.position_px.y, 19.0f);
    EXPECT_LE(v.position_px.y, 20.0f + 16.0f * 1.3f);
  }
  const glm::vec2 size = atlas.measure("Hi\nthere", 16);
  EXPECT_GT(size.x, 16.0f);
  EXPECT_GT(size.y, 30.0f);
}

// A stem thinner than a pixel must still cover a pixel centre wherever the pen
// falls: each quad at the 8 px key size spans at least 2 px (a pixel of margin
// either side, sampled from the mipmapped padding), with uv stretched alike.
TEST(FontAtlas, ThinGlyphsSpanAPixelCentreAtKeySize) {
  const FontAtlas atlas(find_font_file(find_resource_dir()));
  std::vector<TextVertex> quads;
  atlas.layout("lIi|", {10.3f, 20}, 8, {0, 0, 0, 1}, quads);
  ASSERT_EQ(quads.size(), 4u * 6u);
  for (std::size_t q = 0; q < quads.size(); q += 6) {
    const TextVertex &a = quads[q], &e = quads[q + 2];  // top-left, bottom-right
    EXPECT_GE(e.position_px.x - a.position_px.x, 2.0f) << "glyph " << q / 6;
    EXPECT_GT(e.uv.x, a.uv.x);
    // The same texels per pixel across and down: the margin moved uv with the quad.
    const float across = (e.uv.x - a.uv.x) * atlas.width() / (e.position_px.x - a.position_px.x);
    const float down = (e.uv.y - a.uv.y) * atlas.height() / (e.position_px.y - a.position_px.y);
    EXPECT_NEAR(across, down, 1e-3f * down) << "glyph " << q / 6;
  }
}

// viz's table of the font's metrics (viz/font_metrics.inc) is the font's, glyph
// for glyph, at the scale the atlas draws with (ascent − descent = the size):
// the layout measures what is drawn. TUMBLE_UPDATE_FONT_METRICS=1 rewrites it.
TEST(FontMetrics, VizTableIsTheFontsAtTheAtlasScale) {
  const std::filesystem::path ttf = find_font_file(find_resource_dir());
  std::ifstream in(ttf, std::ios::binary);
  const std::vector<unsigned char> data{std::istreambuf_iterator<char>(in), {}};
  stbtt_fontinfo info;
  ASSERT_TRUE(stbtt_InitFont(&info, data.data(), stbtt_GetFontOffsetForIndex(data.data(), 0)));
  const float scale = stbtt_ScaleForPixelHeight(&info, 1.0f);
  const FontAtlas atlas(ttf);
  std::string table;
  std::vector<viz::GlyphMetrics> font;
  for (const char32_t c : atlas.code_points()) {
    int advance = 0, bearing = 0, x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    stbtt_GetCodepointHMetrics(&info, static_cast<int>(c), &advance, &bearing);
    if (!stbtt_GetCodepointBox(&info, static_cast<int>(c), &x0, &y0, &x1, &y1)) x0 = x1 = 0;
    font.push_back({c, advance * scale, x0 * scale, x1 * scale});
    char line[96];
    std::snprintf(line, sizeof line, "{0x%04X, %.5ff, %.5ff, %.5ff},\n", static_cast<unsigned>(c), advance * scale,
                  x0 * scale, x1 * scale);
    table += line;
  }
  const char* update = std::getenv("TUMBLE_UPDATE_FONT_METRICS");
  if (update && std::string(update) == "1") {
    std::ofstream(std::filesystem::path(TUMBLE_SOURCE_DIR) / "src/viz/font_metrics.inc") << table;
    GTEST_SKIP() << "wrote src/viz/font_metrics.inc: rebuild and run again";
  }
  ASSERT_EQ(viz::glyph_table().size(), font.size());
  for (std::size_t i = 0; i < font.size(); ++i) {
    const viz::GlyphMetrics& v = viz::glyph_table()[i];
    ASSERT_EQ(v.code, font[i].code);
    EXPECT_NEAR(v.advance, font[i].advance, 1e-5f) << "U+" << std::hex << static_cast<unsigned>(v.code);
    EXPECT_NEAR(v.ink_x0, font[i].ink_x0, 1e-5f) << "U+" << std::hex << static_cast<unsigned>(v.code);
    EXPECT_NEAR(v.ink_x1, font[i].ink_x1, 1e-5f) << "U+" << std::hex << static_cast<unsigned>(v.code);
  }
  // And the atlas advances its pen by the same amount the table says.
  for (const char* text : {"Hello, world", "\u03c9\u2081 \u2248 I\u2082 \u00d7 \u00bd", "e\u2081 e\u2082 e\u2083"}) {
    float w = 0;
    std::string_view sv(text);
    for (std::size_t i = 0; i < sv.size();) {
      const unsigned char b = static_cast<unsigned char>(sv[i]);
      const int n = b < 0x80 ? 1 : b >= 0xF0 ? 4 : b >= 0xE0 ? 3 : 2;
      char32_t c = n == 1 ? b : b & (0x3F >> (n - 1));
      for (int k = 1; k < n; ++k) c = (c << 6) | (static_cast<unsigned char>(sv[i + k]) & 0x3F);
      i += n;
      w += viz::glyph_metrics(c).advance * 30.0f;
    }
    EXPECT_NEAR(atlas.measure(text, 30.0f).x, w, 0.01f) << text;
  }
}

}  // namespace
}  // namespace tumble::render
