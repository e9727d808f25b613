// Anti-aliasing on the GL path: the renderer's FXAA and MSAA modes both
// soften what the aliased mode draws hard, and FXAA leaves text as drawn.
// FXAA itself on synthetic images: fxaa_test.cpp (no GL).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/image.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"
#include "gl_test.hpp"
#include "test_scenes.hpp"

namespace tumble::render {
namespace {

class AntialiasTest : public test::GlTest {};

int soft_pixels(const io::Image& img) {
  std::set<int> levels;
  int n = 0;
  for (std::size_t i = 0; i + 2 < img.rgb.size(); i += 3) {
    const int r = img.rgb[i], g = img.rgb[i + 1], b = img.rgb[i + 2];
    // Pure arrow colours are saturated; edge blends with the pale background are not.
    n += (r > 60 && g > 60 && b > 60 && std::min({r, g, b}) < 200);
  }
  return n;
}

TEST_F(AntialiasTest, FxaaAndMsaaBothSoftenWhatAliasedDrawsHard) {
  const viz::DrawList dl = test::axis_arrows();
  Renderer none(*context_, 160, 120, scene::Antialias::none), fxaa(*context_, 160, 120, scene::Antialias::fxaa),
      msaa(*context_, 160, 120, scene::Antialias::msaa, 4);
  EXPECT_FALSE(none.fxaa());
  EXPECT_TRUE(fxaa.fxaa());
  EXPECT_EQ(fxaa.samples(), 0);
  EXPECT_EQ(msaa.samples(), 4);
  const io::Image a = none.render(dl), f = fxaa.render(dl), m = msaa.render(dl);
  EXPECT_FALSE(a.rgb == f.rgb);
  EXPECT_FALSE(a.rgb == m.rgb);
  EXPECT_GT(soft_pixels(f), soft_pixels(a)) << "FXAA added no edge blends";
  EXPECT_GT(soft_pixels(m), soft_pixels(a)) << "MSAA added no edge blends";
}

// Text is marked in the alpha channel and left alone: the overlay's pixels
// are the same with and without FXAA when nothing else is drawn near them.
TEST_F(AntialiasTest, FxaaLeavesTextAsDrawn) {
  viz::DrawList dl;
  dl.background = {0.97f, 0.97f, 0.98f, 1.0f};
  dl.texts.push_back({"Illegible 1il|", {8.0f, 8.0f}, 14.0f, {0.1f, 0.1f, 0.1f, 1.0f}});
  Renderer none(*context_, 160, 40, scene::Antialias::none), fxaa(*context_, 160, 40, scene::Antialias::fxaa);
  const io::Image a = none.render(dl), f = fxaa.render(dl);
  EXPECT_TRUE(a.rgb == f.rgb) << "FXAA changed the text";
  int dark = 0;
  for (std::size_t i = 0; i < a.rgb.size(); i += 3) dark += a.rgb[i] < 100;
  EXPECT_GT(dark, 20) << "no text was drawn";
}

}  // namespace
}  // namespace tumble::render
