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

}  // namespace
}  // namespace tumble::render
