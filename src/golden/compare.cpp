#include "golden/compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "base/format.hpp"

namespace tumble::golden {

void check_compare_options(const CompareOptions& c) {
  if (c.max_delta < 0 || c.max_delta > 255) throw InputError("--max-delta: expected 0..255, found " + std::to_string(c.max_delta));
  if (!(c.max_fraction >= 0 && c.max_fraction <= 1))
    throw InputError("--max-fraction: expected a number in [0, 1], found " + format_number(c.max_fraction));
  if (c.max_region < 0) throw InputError("--max-region: expected an integer >= 0, found " + std::to_string(c.max_region));
  if (c.window < 1 || c.window > 255) throw InputError("--window: expected 1..255 px, found " + std::to_string(c.window));
  if (!(c.max_window_mean >= 0 && c.max_window_mean <= 255))
    throw InputError("--max-window-mean: expected a number in [0, 255], found " + format_number(c.max_window_mean));
}

namespace {

bool same_size(const io::Image& a, const io::Image& b) {
  return a.width == b.width && a.height == b.height && a.rgb.size() == b.rgb.size() &&
         a.rgb.size() == static_cast<std::size_t>(a.width) * static_cast<std::size_t>(a.height) * 3;
}

void require_same_size(const io::Image& a, const io::Image& b) {
  if (!same_size(a, b)) throw std::invalid_argument("images of different sizes");
}

/// Largest mean of `d` (w x h, row-major) over a win x win square (clipped to
/// the image when it is smaller): a box filter by running column sums, then a
/// sliding row sum, O(w h) whatever the window.
void worst_window(const std::vector<std::uint8_t>& d, int w, int h, int win, Comparison& c) {
  const int wx = std::min(win, w), wy = std::min(win, h);
  std::vector<std::uint32_t> col(static_cast<std::size_t>(w), 0);
  std::uint32_t best = 0;
  int bx = 0, by = 0;
  for (int y = 0; y < h; ++y) {
    const std::uint8_t* in = d.data() + static_cast<std::size_t>(y) * w;
    if (y >= wy) {
      const std::uint8_t* out = d.data() + static_cast<std::size_t>(y - wy) * w;
      for (int x = 0; x < w; ++x) col[x] += static_cast<std::uint32_t>(in[x]) - out[x];  // wraps back to >= 0
    } else {
      for (int x = 0; x < w; ++x) col[x] += in[x];
    }
    if (y < wy - 1) continue;
    std::uint32_t s = 0;
    for (int x = 0; x < wx; ++x) s += col[x];
    for (int x = wx;; ++x) {
      if (s > best) best = s, bx = x - wx, by = y - wy + 1;
      if (x == w) break;
      s += col[x] - col[x - wx];
    }
  }
  c.window_mean = static_cast<double>(best) / (static_cast<double>(wx) * wy);
  if (best > 0) c.window_box = {bx, by, bx + wx - 1, by + wy - 1};
}

/// Largest 8-connected region of the pixels with d > max_delta, by flood fill
/// with an explicit stack. Consumes `d` (visited pixels are set to 0).
void largest_region(std::vector<std::uint8_t>& over, int max_delta, int w, int h, Comparison& c) {
  for (std::uint8_t& v : over) v = v > max_delta;
  std::vector<int> stack;
  const std::uint8_t* base = over.data();
  for (int start = 0; start < w * h; ++start) {
    const void* next = std::memchr(base + start, 1, static_cast<std::size_t>(w * h - start));  // skips runs of 0 fast
    if (!next) break;
    start = static_cast<int>(static_cast<const std::uint8_t*>(next) - base);
    over[start] = 0;
    stack.assign(1, start);
    long size = 0;
    Box b{w, h, -1, -1};
    while (!stack.empty()) {
      const int p = stack.back();
      stack.pop_back();
      ++size;
      const int x = p % w, y = p / w;
      b = {std::min(b.x0, x), std::min(b.y0, y), std::max(b.x1, x), std::max(b.y1, y)};
      for (int ny = std::max(0, y - 1); ny <= std::min(h - 1, y + 1); ++ny)
        for (int nx = std::max(0, x - 1); nx <= std::min(w - 1, x + 1); ++nx) {
          const int q = ny * w + nx;
          if (over[q]) over[q] = 0, stack.push_back(q);
        }
    }
    if (size > c.region) c.region = size, c.region_box = b;
  }
}

}  // namespace

namespace {

// d = each pixel's largest channel difference; sets c's over, max_delta,
// fraction and RMS. Row by row in simple loops the compiler vectorizes:
// |a - e| per byte, the squares, the largest of each pixel's three, then the counts.
std::vector<std::uint8_t> pixel_deltas(const io::Image& actual, const io::Image& expected, int max_delta, Comparison& c) {
  const int w = actual.width, h = actual.height;
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  // Locals, not members of c: stores through uint8_t pointers may alias them.
  std::vector<std::uint8_t> d(n);
  std::uint64_t sum_sq = 0;
  long over = 0;
  int max_d = 0;
  std::vector<std::uint8_t> ad(static_cast<std::size_t>(w) * 3);
  for (int y = 0; y < h; ++y) {
    const std::size_t row = static_cast<std::size_t>(y) * w;
    const std::uint8_t* a = actual.rgb.data() + row * 3;
    const std::uint8_t* e = expected.rgb.data() + row * 3;
    std::uint8_t* dr = d.data() + row;
    std::uint32_t row_sq = 0;  // <= 16384 px * 3 * 255^2 < 2^32
    for (int j = 0; j < 3 * w; ++j) {
      ad[j] = static_cast<std::uint8_t>(a[j] > e[j] ? a[j] - e[j] : e[j] - a[j]);
      row_sq += static_cast<std::uint32_t>(ad[j] * ad[j]);
    }
    sum_sq += row_sq;
    for (int x = 0; x < w; ++x) dr[x] = std::max(ad[3 * x], std::max(ad[3 * x + 1], ad[3 * x + 2]));
    for (int x = 0; x < w; ++x) {
      over += dr[x] > max_delta;
      max_d = std::max(max_d, int(dr[x]));
    }
  }
  c.over = over;
  c.max_delta = max_d;
  c.fraction = n ? static_cast<double>(c.over) / static_cast<double>(n) : 0.0;
  c.rms = n ? std::sqrt(static_cast<double>(sum_sq) / (3.0 * static_cast<double>(n))) : 0.0;
  return d;
}

// The one-line summary: each measure beside its limit, then what failed.
std::string comparison_summary(const Comparison& c, const CompareOptions& o, std::size_t n) {
  char line[400];
  auto at = [](const Box& b) {
    return b.empty() ? std::string() : " at (" + std::to_string(b.x0) + "," + std::to_string(b.y0) + ")-(" +
                                           std::to_string(b.x1) + "," + std::to_string(b.y1) + ")";
  };
  std::snprintf(line, sizeof line, "%ld of %zu pixels over delta %d (fraction %.6f, limit %.6f), largest region %ld px%s (limit %ld), ",
                c.over, n, o.max_delta, c.fraction, o.max_fraction, c.region, at(c.region_box).c_str(), o.max_region);
  std::string sum = line;
  std::snprintf(line, sizeof line, "worst %dx%d mean %.2f%s (limit %g), max delta %d, RMS %.3f", o.window, o.window,
                c.window_mean, at(c.window_box).c_str(), o.max_window_mean, c.max_delta, c.rms);
  sum += line;
  if (!c.pass)
    sum += std::string("; over the limit:") + (c.fraction_ok ? "" : " fraction") + (c.region_ok ? "" : " region") +
           (c.window_ok ? "" : " window-mean");
  return sum;
}

}  // namespace

Comparison compare_images(const io::Image& actual, const io::Image& expected, const CompareOptions& o) {
  Comparison c;
  c.width = actual.width;
  c.height = actual.height;
  if (!same_size(actual, expected)) {
    c.size_mismatch = true;
    char line[400];
    std::snprintf(line, sizeof line, "sizes differ: actual %dx%d, expected %dx%d", actual.width, actual.height,
                  expected.width, expected.height);
    c.summary = line;
    return c;
  }
  const int w = actual.width, h = actual.height;
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  std::vector<std::uint8_t> d = pixel_deltas(actual, expected, o.max_delta, c);
  if (n) {
    worst_window(d, w, h, std::max(1, o.window), c);
    if (c.over) largest_region(d, o.max_delta, w, h, c);
  }
  c.fraction_ok = c.fraction <= o.max_fraction;
  c.region_ok = c.region <= o.max_region;
  c.window_ok = c.window_mean <= o.max_window_mean;
  c.pass = c.fraction_ok && c.region_ok && c.window_ok;
  c.summary = comparison_summary(c, o, n);
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

void outline_box(io::Image& img, const Box& box, const std::uint8_t (&rgb)[3], int margin) {
  if (box.empty() || img.width <= 0 || img.height <= 0) return;
  const int x0 = box.x0 - margin, y0 = box.y0 - margin, x1 = box.x1 + margin, y1 = box.y1 + margin;
  auto put = [&](int x, int y) {
    if (x < 0 || y < 0 || x >= img.width || y >= img.height) return;
    std::uint8_t* p = img.rgb.data() + (static_cast<std::size_t>(y) * img.width + x) * 3;
    for (int ch = 0; ch < 3; ++ch) p[ch] = rgb[ch];
  };
  for (int x = x0; x <= x1; ++x) put(x, y0), put(x, y1);
  for (int y = y0; y <= y1; ++y) put(x0, y), put(x1, y);
}

void outline_offenders(io::Image& img, const Comparison& c) {
  static constexpr std::uint8_t kYellow[3] = {255, 230, 0}, kCyan[3] = {0, 230, 255};
  if (!c.window_ok) outline_box(img, c.window_box, kCyan, 3);
  outline_box(img, c.region_box, kYellow, 2);
}

}  // namespace tumble::golden
