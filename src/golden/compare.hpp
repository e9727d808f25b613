// Image comparison for golden tests. Per pixel the largest difference over the
// three channels, D (0..255). Three figures must stay within limits:
//  - global: the fraction of pixels with D > max_delta (a widespread change);
//  - local:  the largest 8-connected region of pixels with D > max_delta (a
//    small, solid change such as a moved highlight or a 1 px shift of a body);
//  - pooled: the largest mean of D over a window x window square, computed
//    with a summed-area table (Crow 1984, "Summed-area tables for texture
//    mapping", SIGGRAPH), which catches a faint but coherent patch.
// Scattered single pixels and low-bit noise, the typical driver and
// anti-aliasing differences, stay under all three. The defaults come from
// measurements on llvmpipe and on deliberate small changes (docs/golden.md).
#pragma once

#include <string>

#include "io/image.hpp"

namespace tumble::golden {

struct CompareOptions {
  int max_delta = 8;             ///< 0..255: a pixel differs when its largest channel delta is > this
  double max_fraction = 0.0005;  ///< pass when (pixels over max_delta) / (all pixels) <= this
  long max_region = 6;           ///< px: pass when the largest connected region of differing pixels <= this
  int window = 9;                ///< px: side of the square window of the pooled mean
  double max_window_mean = 4;    ///< 0..255 levels: pass when the largest window mean of D <= this
};

/// Throws InputError naming the option (--max-delta, --max-fraction,
/// --max-region, --window, --max-window-mean) of a value out of its range.
void check_compare_options(const CompareOptions& c);

/// Inclusive pixel rectangle; empty when x1 < x0.
struct Box {
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
  bool empty() const { return x1 < x0 || y1 < y0; }
};

struct Comparison {
  bool size_mismatch = false;  ///< then nothing else is filled in and `pass` is false
  int width = 0, height = 0;   ///< of the actual image
  int max_delta = 0;           ///< largest channel difference over the image, 0..255
  long over = 0;               ///< pixels whose largest channel delta > options.max_delta
  double fraction = 0;         ///< over / (width * height)
  double rms = 0;              ///< root mean square over all channels, in 0..255 levels
  long region = 0;             ///< px in the largest 8-connected region of over pixels
  Box region_box;              ///< its bounding box (empty when region == 0)
  double window_mean = 0;      ///< largest mean of D over a window (levels)
  Box window_box;              ///< where (the first such window in row order)
  bool fraction_ok = true, region_ok = true, window_ok = true;
  bool pass = false;
  std::string summary;         ///< one line with the figures, or what was wrong
};

/// Compares `actual` with `expected`. Never throws for valid Images;
/// different sizes give size_mismatch (and pass = false).
Comparison compare_images(const io::Image& actual, const io::Image& expected,
                          const CompareOptions& options = {});

/// |actual - expected| per channel times `gain` (clamped to 255) on black:
/// differences of a few levels become visible. Sizes must match.
io::Image amplified_difference(const io::Image& actual, const io::Image& expected, int gain = 16);

/// The pixels over the threshold in magenta, on the expected image darkened
/// to a quarter for context. Sizes must match.
io::Image over_threshold_mask(const io::Image& actual, const io::Image& expected, int max_delta);

/// Draws a 1 px outline `margin` px outside `box` (clipped to the image) in
/// colour `rgb`; the pixels inside stay visible. Does nothing for an empty box.
void outline_box(io::Image& img, const Box& box, const std::uint8_t (&rgb)[3], int margin = 2);

/// Outlines where `c` found the change: the largest region in yellow and,
/// when it is over its limit, the worst window in cyan.
void outline_offenders(io::Image& img, const Comparison& c);

}  // namespace tumble::golden
