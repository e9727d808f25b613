// Image comparison for golden tests: per pixel the largest difference over the
// three channels, against a threshold; the test fails when more than a
// fraction of the pixels are over it. The defaults tolerate llvmpipe's
// low-bit differences between CPUs and Mesa versions (anti-aliased edges move
// by a few levels) and catch a changed colour, a moved edge or a missing arrow.
#pragma once

#include <string>

#include "io/image.hpp"

namespace tumble::golden {

struct CompareOptions {
  int max_delta = 8;             ///< 0..255: a pixel differs when its largest channel delta is > this
  double max_fraction = 0.0005;  ///< pass when (pixels over max_delta) / (all pixels) <= this
};

struct Comparison {
  bool size_mismatch = false;  ///< then nothing else is filled in and `pass` is false
  int width = 0, height = 0;   ///< of the actual image
  int max_delta = 0;           ///< largest channel difference over the image, 0..255
  long over = 0;               ///< pixels whose largest channel delta > options.max_delta
  double fraction = 0;         ///< over / (width * height)
  double rms = 0;              ///< root mean square over all channels, in 0..255 levels
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

}  // namespace tumble::golden
