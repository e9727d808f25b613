#include <gtest/gtest.h>

#include "render/font_atlas.hpp"
#include "render/resource_dir.hpp"

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

}  // namespace
}  // namespace tumble::render
