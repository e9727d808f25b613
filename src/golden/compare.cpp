#include "golden/compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace tumble::golden {

namespace {

bool same_size(const io::Image& a, const io::Image& b) {
  return a.width == b.width && a.height == b.height && a.rgb.size() == b.rgb.size() &&
         a.rgb.size() == static_cast<std::size_t>(a.width) * static_cast<std::size_t>(a.height) * 3;
}

void require_same_size(const io::Image& a, const io::Image& b) {
  if (!same_size(a, b)) throw std::invalid_argument("images of different sizes");
}

}  // namespace

Comparison compare_images(const io::Image& actual, const io::Image& expected, const CompareOptions& o) {
  Comparison c;
  c.width = actual.width;
  c.height = actual.height;
  char line[200];
  if (!same_size(actual, expected)) {
    c.size_mismatch = true;
    std::snprintf(line, sizeof line, "sizes differ: actual %dx%d, expected %dx%d", actual.width, actual.height,
                  expected.width, expected.height);
    c.summary = line;
    return c;
  }
  const std::size_t n = static_cast<std::size_t>(actual.width) * static_cast<std::size_t>(actual.height);
  double sum_sq = 0;
  for (std::size_t i = 0; i < n; ++i) {
    int m = 0;
    for (int ch = 0; ch < 3; ++ch) {
      const int d = std::abs(int(actual.rgb[i * 3 + ch]) - int(expected.rgb[i * 3 + ch]));
      m = std::max(m, d);
      sum_sq += double(d) * d;
    }
    c.max_delta = std::max(c.max_delta, m);
    if (m > o.max_delta) ++c.over;
  }
  c.fraction = n ? static_cast<double>(c.over) / static_cast<double>(n) : 0.0;
  c.rms = n ? std::sqrt(sum_sq / (3.0 * static_cast<double>(n))) : 0.0;
  c.pass = c.fraction <= o.max_fraction;
  std::snprintf(line, sizeof line,
                "%ld of %zu pixels over delta %d (fraction %.6f, limit %.6f), max delta %d, RMS %.3f", c.over, n,
                o.max_delta, c.fraction, o.max_fraction, c.max_delta, c.rms);
  c.summary = line;
  return c;
}

io::Image amplified_difference(const io::Image& actual, const io::Image& expected, int gain) {
  require_same_size(actual, expected);
  io::Image out{actual.width, actual.height, std::vector<std::uint8_t>(actual.rgb.size())};
  for (std::size_t i = 0; i < actual.rgb.size(); ++i)
    out.rgb[i] = static_cast<std::uint8_t>(std::min(255, std::abs(int(actual.rgb[i]) - int(expected.rgb[i])) * gain));
  return out;
}

io::Image over_threshold_mask(const io::Image& actual, const io::Image& expected, int max_delta) {
  require_same_size(actual, expected);
  io::Image out{actual.width, actual.height, std::vector<std::uint8_t>(actual.rgb.size())};
  for (std::size_t i = 0; i < actual.rgb.size(); i += 3) {
    int m = 0;
    for (int ch = 0; ch < 3; ++ch) m = std::max(m, std::abs(int(actual.rgb[i + ch]) - int(expected.rgb[i + ch])));
    if (m > max_delta) {
      out.rgb[i] = 255;
      out.rgb[i + 1] = 0;
      out.rgb[i + 2] = 255;
    } else {
      for (int ch = 0; ch < 3; ++ch) out.rgb[i + ch] = static_cast<std::uint8_t>(expected.rgb[i + ch] / 4);
    }
  }
  return out;
}

}  // namespace tumble::golden
