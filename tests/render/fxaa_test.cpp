// FXAA on synthetic frames (no GL): a hard staircase gets intermediate
// shades, flat areas and axis-aligned edges stay exact, marked (text) pixels
// are copied, and the rows come out top-down.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "render/fxaa.hpp"

namespace tumble::render {
namespace {

constexpr int kW = 96, kH = 64;

// RGBA, bottom row first; `dark(x, y)` with y counted up, as GL does.
template <class F>
std::vector<std::uint8_t> frame(F dark, std::uint8_t alpha = 255) {
  std::vector<std::uint8_t> rgba(std::size_t{kW} * kH * 4);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      for (int c = 0; c < 4; ++c) rgba[(std::size_t(y) * kW + x) * 4 + c] = c == 3 ? alpha : dark(x, y) ? 0 : 255;
  return rgba;
}

bool slope(int x, int y) { return 3 * y > x + 40; }  // black above a line of slope 1/3: hard steps

TEST(Fxaa, SmoothsAStaircaseAndKeepsFlatAreas) {
  const auto rgba = frame(slope);
  io::Image out;
  Fxaa().apply(rgba.data(), kW, kH, out);
  ASSERT_EQ(out.width, kW);
  ASSERT_EQ(out.height, kH);
  int between = 0, flat_changed = 0;
  for (int row = 0; row < kH; ++row) {
    const int y = kH - 1 - row;  // GL row of this (top-down) image row
    for (int x = 0; x < kW; ++x) {
      const int v = out.pixel(x, row)[0];
      bool near = false;  // within 3 px of the edge
      for (int dy = -3; dy <= 3; ++dy)
        for (int dx = -3; dx <= 3; ++dx) near = near || slope(x + dx, y + dy) != slope(x, y);
      if (!near) flat_changed += v != (slope(x, y) ? 0 : 255);
      if (near && v > 20 && v < 235) ++between;
    }
  }
  EXPECT_EQ(flat_changed, 0);
  // The edge crosses all kW columns; most of its steps get intermediate shades.
  EXPECT_GT(between, kW / 2) << "FXAA left the staircase hard";
}

// A straight edge has no steps to walk: only FXAA's sub-pixel term touches
// it, by a few percent, on the two rows beside it.
TEST(Fxaa, BarelyTouchesAnAxisAlignedEdgeAndWritesTopDown) {
  const auto rgba = frame([](int, int y) { return y < 20; });  // dark bottom rows
  io::Image out;
  Fxaa().apply(rgba.data(), kW, kH, out);
  for (int row = 0; row < kH; ++row) {
    const int y = kH - 1 - row;
    const int want = y < 20 ? 0 : 255, slack = y == 19 || y == 20 ? 20 : 0;
    for (int x = 0; x < kW; ++x) ASSERT_NEAR(out.pixel(x, row)[1], want, slack) << x << ", " << row;
  }
}

TEST(Fxaa, CopiesMarkedPixels) {
  const auto rgba = frame(slope, 200);  // alpha < 255 everywhere: all text
  io::Image out;
  Fxaa().apply(rgba.data(), kW, kH, out);
  for (int row = 0; row < kH; ++row)
    for (int x = 0; x < kW; ++x) ASSERT_EQ(out.pixel(x, row)[0], slope(x, kH - 1 - row) ? 0 : 255);
}

}  // namespace
}  // namespace tumble::render
