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
  /// `threads`: 1, or 2 to split the rows (same bytes either way).
  void apply(const std::uint8_t* rgba, int width, int height, io::Image& out, int threads = 2);

 private:
  std::vector<std::uint8_t> luma_;  // per pixel, 0..255, reused across frames
};

/// A frame as read back, before its post-processing: what the renderer hands
/// to the frame encoder's threads, so FXAA runs there while the next frame draws.
struct RawFrame {
  std::vector<std::uint8_t> rgba;  ///< width × height RGBA8, bottom row first
  int width = 0, height = 0;
  bool fxaa = false;               ///< anti-alias with FXAA when finishing
  long index = -1;                 ///< the caller's frame number (Renderer::render_overlapped)
};

/// `raw` as a top-down RGB image: FXAA'd (using `fxaa`'s scratch) or converted.
void finish_frame(const RawFrame& raw, io::Image& out, Fxaa& fxaa, int threads = 2);

}  // namespace tumble::render
