// The image comparison (GL-free): global fraction, largest connected region
// and the windowed mean on synthetic images (the cases it must tell apart).
#include <algorithm>
#include <cstdint>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "base/error.hpp"
#include "golden/compare.hpp"

namespace {

using tumble::golden::Box;
using tumble::golden::compare_images;
using tumble::golden::CompareOptions;
using tumble::io::Image;

Image flat(int w, int h, std::uint8_t v) { return {w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h * 3, v)}; }

/// A smooth, non-flat scene-like image (values 20..219, so ±40 never clips).
Image gradient(int w, int h) {
  Image img{w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h * 3)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int ch = 0; ch < 3; ++ch)
        img.rgb[(static_cast<std::size_t>(y) * w + x) * 3 + ch] = static_cast<std::uint8_t>((x + 2 * y + 40 * ch) % 200 + 20);
  return img;
}

void add(Image& img, int x, int y, int ch, int delta) {
  auto& v = img.rgb[(static_cast<std::size_t>(y) * img.width + x) * 3 + ch];
  v = static_cast<std::uint8_t>(std::clamp(int(v) + delta, 0, 255));
}

void patch(Image& img, int x0, int y0, int side, int delta) {
  for (int y = y0; y < y0 + side; ++y)
    for (int x = x0; x < x0 + side; ++x)
      for (int ch = 0; ch < 3; ++ch) add(img, x, y, ch, delta);
}

// Both the golden size and 720p.
const std::pair<int, int> kSizes[] = {{320, 240}, {1280, 720}};

TEST(CompareLocal, Patch5x5By40Fails) {
  for (auto [w, h] : kSizes) {
    const Image a = gradient(w, h);
    Image b = a;
    patch(b, 100, 80, 5, 40);
    const auto c = compare_images(b, a);
    EXPECT_FALSE(c.pass) << c.summary;
    EXPECT_EQ(c.region, 25);
    EXPECT_EQ(c.region_box.x0, 100);
    EXPECT_EQ(c.region_box.y0, 80);
    EXPECT_EQ(c.region_box.x1, 104);
    EXPECT_EQ(c.region_box.y1, 84);
    EXPECT_NEAR(c.window_mean, 25 * 40 / 81.0, 1e-12);
    EXPECT_TRUE(c.fraction_ok) << "the global fraction alone would pass it: " << c.summary;
  }
}

TEST(CompareLocal, Patch3x3By60Fails) {
  for (auto [w, h] : kSizes) {
    const Image a = gradient(w, h);
    Image b = a;
    patch(b, w - 3, h - 3, 3, -60);  // in the corner: the window is clipped to the image
    const auto c = compare_images(b, a);
    EXPECT_FALSE(c.pass) << c.summary;
    EXPECT_EQ(c.region, 9);
    EXPECT_NEAR(c.window_mean, 9 * 60 / 81.0, 1e-12);
    EXPECT_EQ(c.window_box.x1, w - 1);
    EXPECT_EQ(c.window_box.y1, h - 1);
  }
}

TEST(CompareLocal, IsolatedPixelsOffByUpTo20OnFourHundredthsOfAPercentPass) {
  for (auto [w, h] : kSizes) {
    const Image a = gradient(w, h);
    Image b = a;
    std::mt19937 rng(4);
    const long want = static_cast<long>(w) * h * 4 / 10000;  // 0.04 %
    std::set<std::pair<int, int>> taken;
    auto near_taken = [&](int x, int y) {
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          if (taken.count({x + dx, y + dy})) return true;
      return false;
    };
    while (static_cast<long>(taken.size()) < want) {
      const int x = static_cast<int>(rng() % w), y = static_cast<int>(rng() % h);
      if (near_taken(x, y)) continue;  // isolated: no 8-neighbour changed
      taken.insert({x, y});
      const int mag = 20 - static_cast<int>(rng() % 12);  // 9..20: all over the threshold of 8
      add(b, x, y, static_cast<int>(rng() % 3), rng() % 2 ? mag : -mag);
    }
    const auto c = compare_images(b, a);
    EXPECT_TRUE(c.pass) << w << "x" << h << ": " << c.summary;
    EXPECT_EQ(c.over, want);
    EXPECT_EQ(c.region, 1);
  }
}

TEST(CompareLocal, ThreeLsbNoiseOnTwoPercentPasses) {
  for (auto [w, h] : kSizes) {
    const Image a = gradient(w, h);
    Image b = a;
    std::mt19937 rng(2);
    const std::size_t n = static_cast<std::size_t>(w) * h;
    std::vector<bool> taken(n);
    for (std::size_t k = 0; k < n / 50;) {  // 2 % of the pixels, each once
      const std::size_t p = rng() % n;
      if (taken[p]) continue;
      taken[p] = true;
      ++k;
      for (int ch = 0; ch < 3; ++ch) b.rgb[p * 3 + ch] = static_cast<std::uint8_t>(int(a.rgb[p * 3 + ch]) + int(rng() % 7) - 3);
    }
    const auto c = compare_images(b, a);
    EXPECT_TRUE(c.pass) << c.summary;
    EXPECT_EQ(c.max_delta, 3);
    EXPECT_EQ(c.region, 0);
    EXPECT_GT(c.window_mean, 0.0);
  }
}

// A thin diagonal line is one 8-connected region; a 1 px shift of an edge is such a line.
TEST(CompareLocal, DiagonalLineIsOneRegionAndFails) {
  const Image a = gradient(320, 240);
  Image b = a;
  for (int i = 0; i < 20; ++i) add(b, 50 + i, 60 + i, 1, 100);
  const auto c = compare_images(b, a);
  EXPECT_EQ(c.region, 20);
  EXPECT_EQ(c.region_box.x0, 50);
  EXPECT_EQ(c.region_box.y1, 79);
  EXPECT_FALSE(c.region_ok);
  EXPECT_FALSE(c.pass) << c.summary;
  EXPECT_NE(c.summary.find("region"), std::string::npos) << c.summary;
}

// A faint but coherent 9x9 patch (+7, nothing over the threshold) fails by the windowed mean alone.
TEST(CompareLocal, FaintPatchFailsByTheWindowedMeanAlone) {
  const Image a = gradient(320, 240);
  Image b = a;
  patch(b, 30, 40, 9, 7);
  const auto c = compare_images(b, a);
  EXPECT_EQ(c.over, 0);
  EXPECT_DOUBLE_EQ(c.window_mean, 7.0);
  EXPECT_EQ(c.window_box.x0, 30);
  EXPECT_EQ(c.window_box.y0, 40);
  EXPECT_FALSE(c.window_ok);
  EXPECT_FALSE(c.pass);
  // Loosened limits pass it: each figure is its own limit.
  CompareOptions loose;
  loose.max_window_mean = 7;
  EXPECT_TRUE(compare_images(b, a, loose).pass);
}

TEST(CompareLocal, OutlineIsDrawnOutsideTheBoxAndClipped) {
  Image img = flat(20, 10, 0);
  const std::uint8_t red[3] = {255, 0, 0};
  tumble::golden::outline_box(img, Box{1, 1, 3, 3}, red, 2);
  auto px = [&](int x, int y) { return img.pixel(x, y)[0]; };
  EXPECT_EQ(px(5, 5), 255);  // corner at (x1 + 2, y1 + 2)
  EXPECT_EQ(px(5, 0), 255);  // the left and top sides are off the image; the others are clipped
  EXPECT_EQ(px(2, 2), 0);    // inside stays untouched
  EXPECT_EQ(px(6, 6), 0);
  tumble::golden::outline_box(img, Box{}, red);  // empty: nothing
}

// ---- the global figures ----

TEST(Compare, IdenticalImagesPassWithZeroFigures) {
  const auto a = flat(40, 30, 100);
  const auto c = compare_images(a, a);
  EXPECT_TRUE(c.pass);
  EXPECT_EQ(c.max_delta, 0);
  EXPECT_EQ(c.over, 0);
  EXPECT_EQ(c.rms, 0.0);
  EXPECT_EQ(c.region, 0);
  EXPECT_EQ(c.window_mean, 0.0);
  EXPECT_TRUE(c.region_box.empty());
}

TEST(Compare, LowBitNoiseUnderTheThresholdPasses) {
  auto a = flat(40, 30, 100), b = a;
  for (std::size_t i = 0; i < b.rgb.size(); i += 7) b.rgb[i] = static_cast<std::uint8_t>(100 + (i % 9) - 4);
  const auto c = compare_images(a, b);
  EXPECT_TRUE(c.pass) << c.summary;
  EXPECT_EQ(c.max_delta, 4);
  EXPECT_EQ(c.over, 0);
}

TEST(Compare, CountsPixelsOverTheThresholdByTheirLargestChannel) {
  auto a = flat(100, 100, 100), b = a;
  b.rgb[0 * 3 + 2] = 109;  // blue +9: over 8
  b.rgb[1 * 3 + 0] = 108;  // +8: not over
  CompareOptions strict;
  strict.max_fraction = 0;
  const auto c = compare_images(a, b, strict);
  EXPECT_EQ(c.over, 1);
  EXPECT_EQ(c.max_delta, 9);
  EXPECT_DOUBLE_EQ(c.fraction, 1e-4);
  EXPECT_FALSE(c.pass);  // max_fraction 0
  EXPECT_TRUE(compare_images(a, b, CompareOptions{8, 1e-4}).pass);
  const auto mask = tumble::golden::over_threshold_mask(a, b, 8);
  EXPECT_EQ(mask.rgb[0], 255);
  EXPECT_EQ(mask.rgb[3], 108 / 4);  // not over: the expected pixel, darkened
  EXPECT_EQ(tumble::golden::amplified_difference(a, b).rgb[2], 9 * 16);
}

TEST(Compare, DifferentSizesFailWithoutThrowing) {
  const auto c = compare_images(flat(32, 24, 0), flat(24, 32, 0));
  EXPECT_FALSE(c.pass);
  EXPECT_TRUE(c.size_mismatch);
  EXPECT_NE(c.summary.find("32x24"), std::string::npos) << c.summary;
}

// Same pixel count, other shape: 10x20 is not 20x10.
TEST(Compare, TransposedSizesAreASizeMismatch) {
  const auto c = compare_images(flat(10, 20, 50), flat(20, 10, 50));
  EXPECT_TRUE(c.size_mismatch);
  EXPECT_FALSE(c.pass);
}

// "Over" is strictly more than max_delta: a patch of exactly max_delta is no region.
TEST(CompareLocal, APatchOfExactlyMaxDeltaIsNotOver) {
  const Image a = gradient(64, 48);
  Image b = a;
  const CompareOptions o;
  patch(b, 10, 10, 5, o.max_delta);
  const auto c = compare_images(b, a, o);
  EXPECT_EQ(c.max_delta, o.max_delta);
  EXPECT_EQ(c.over, 0);
  EXPECT_EQ(c.region, 0);
  patch(b, 10, 10, 5, 1);
  EXPECT_EQ(compare_images(b, a, o).region, 25);
  Image ringed = a;  // 5x5 over, in a ring of pixels exactly at max_delta: the region is the 25
  patch(ringed, 9, 9, 7, o.max_delta);
  patch(ringed, 10, 10, 5, 1);
  EXPECT_EQ(compare_images(ringed, a, o).region, 25);
}

// An image lower than the window: the window is clipped to its height, not skipped.
TEST(CompareLocal, TheWindowIsClippedToALowImage) {
  const Image a = flat(40, 5, 100);
  Image b = a;
  patch(b, 20, 1, 3, 40);
  CompareOptions o;
  o.window = 9;
  const auto c = compare_images(b, a, o);
  EXPECT_NEAR(c.window_mean, 9 * 40 / (9.0 * 5), 1e-12);
  EXPECT_EQ(c.window_box.y0, 0);
  EXPECT_EQ(c.window_box.y1, 4);
}

TEST(Compare, OptionsOutOfRangeAreRefused) {
  CompareOptions o;
  o.window = 255;
  EXPECT_NO_THROW(tumble::golden::check_compare_options(o));
  o.window = 256;
  EXPECT_THROW(tumble::golden::check_compare_options(o), tumble::InputError);
  o.window = 0;
  EXPECT_THROW(tumble::golden::check_compare_options(o), tumble::InputError);
}

}  // namespace
