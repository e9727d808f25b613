// FXAA on the CPU, on the frame as read back: after T. Lottes, "FXAA"
// (NVIDIA white paper, 2009), the FXAA 3.11 quality path. It replaces MSAA's
// samples at a few ms a frame: on llvmpipe the same algorithm as a fragment
// shader cost more than drawing the frame (its texture fetches are gathers).
// GL-free, so tests run it on synthetic images.
#pragma once

#include <cstdint>
#include <vector>

#include "io/image.hpp"

namespace tumble::render {

/// One row of RGBA8 pixels to RGB8 (alpha dropped).
void rgba_row_to_rgb(const std::uint8_t* rgba, int width, std::uint8_t* rgb);

class Fxaa {
 public:
  /// `rgba`: width × height RGBA8, bottom row first (glReadPixels' order).
  /// Writes the anti-aliased frame to `out` as top-down RGB, reusing its
  /// storage. A pixel whose 3x3 neighbourhood holds an alpha below 255 is
  /// copied unchanged: the renderer marks text that way (its glyphs are
  /// anti-aliased already, and FXAA would blur their stems).
  void apply(const std::uint8_t* rgba, int width, int height, io::Image& out);

 private:
  std::vector<std::uint8_t> luma_;  // per pixel, 0..255, reused across frames
};

}  // namespace tumble::render
