// Text is measured as drawn: the box the layout gives a string (viz::text_box,
// from viz/font_metrics.hpp) is where its glyphs land in the rendered frame,
// within 1 px, at every size the text roles use from 360p to 1080p and beyond;
// centred text is centred.
#include <algorithm>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "render/gl_context.hpp"
#include "render/renderer.hpp"
#include "viz/text_layout.hpp"

namespace tumble::render {
namespace {

constexpr int kW = 1600, kH = 200;

std::unique_ptr<GlContext> context_or_skip() {
  try {
    return create_gl_context(default_gl_backend());
  } catch (const std::runtime_error& e) {
    const char* req = std::getenv("TUMBLE_REQUIRE_GL");
    if (req && std::string(req) == "1") ADD_FAILURE() << "TUMBLE_REQUIRE_GL=1: " << e.what();
    return nullptr;
  }
}

// The ink of `t` drawn alone: pixels that differ from the same frame without it.
viz::Box drawn_ink(Renderer& r, const viz::TextItem& t) {
  viz::DrawList bare;
  viz::DrawList with = bare;
  with.texts.push_back(t);
  const io::Image a = r.render(bare), b = r.render(with);
  viz::Box ink{1e9f, 1e9f, -1e9f, -1e9f};
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const std::uint8_t *p = a.pixel(x, y), *q = b.pixel(x, y);
      // A quarter covered or more: a glyph's edge, not the mipmap's faint halo.
      if (std::max({std::abs(p[0] - q[0]), std::abs(p[1] - q[1]), std::abs(p[2] - q[2])}) < 60) continue;
      ink = {std::min(ink.x0, float(x)), std::min(ink.y0, float(y)), std::max(ink.x1, float(x + 1)),
             std::max(ink.y1, float(y + 1))};
    }
  return ink;
}

TEST(TextExtent, LayoutBoxIsTheDrawnInkWithinOnePixel) {
  auto context = context_or_skip();
  if (!context) GTEST_SKIP() << "no GL context";
  Renderer renderer(*context, kW, kH, scene::Antialias::none);
  const char* texts[] = {"Why a spinning T-handle flips", "\u03c9\u2081 \u2248 I\u2082 \u00d7 \u00bd", "e\u2081",
                         "Ljqy| (AVAW)", "t =   1.23 s   |dE/E| < 1e-13", "\u03a0: L in body axes"};
  // The text roles' sizes (viz::text_px) at 360p, 540p, 720p and 1080p, and the title at 1080p.
  const float sizes[] = {7.92f, 8.64f, 12.24f, 15.66f, 18.36f, 25.92f, 36.72f, 75.6f};
  for (const char* text : texts)
    for (const float size : sizes) {
      const viz::TextItem t{text, {40.3f, 30.0f}, size, {0.1f, 0.1f, 0.12f, 1.0f}, "caption"};
      const viz::Box box = viz::text_box(t), ink = drawn_ink(renderer, t);
      EXPECT_NEAR(ink.x0, box.x0, 1.0f) << "'" << text << "' at " << size << " px";
      EXPECT_NEAR(ink.x1, box.x1, 1.0f) << "'" << text << "' at " << size << " px";
      // Down, the ink stays within the lines' box (ascent to descent).
      EXPECT_GE(ink.y0, box.y0 - 1.0f) << "'" << text << "' at " << size << " px";
      EXPECT_LE(ink.y1, box.y1 + 1.0f) << "'" << text << "' at " << size << " px";
    }
}

TEST(TextExtent, CentredTextIsCentred) {
  auto context = context_or_skip();
  if (!context) GTEST_SKIP() << "no GL context";
  Renderer renderer(*context, kW, kH, scene::Antialias::none);
  for (const float size : {9.0f, 24.5f, 75.6f}) {
    const std::string text = "Why a spinning T-handle flips";
    const viz::TextItem t{text, {viz::centred_x(text, size, 0.5f * kW), 20.0f}, size, {0, 0, 0, 1}, "title"};
    const viz::Box ink = drawn_ink(renderer, t);
    EXPECT_NEAR(0.5f * (ink.x0 + ink.x1), 0.5f * kW, 1.0f) << size << " px";
  }
}

}  // namespace
}  // namespace tumble::render
