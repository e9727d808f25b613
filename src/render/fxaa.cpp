#include "render/fxaa.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <thread>

namespace tumble::render {
namespace {

constexpr float kEdgeThreshold = 0.166f;     // contrast, relative to the local max, that is an edge
constexpr float kEdgeThresholdMin = 0.0833f; // darker contrast than this is left alone (3.11 defaults)
// Strength of the sub-pixel smoothing: 3.11 suggests 0.75; against 4x MSAA
// (tumble compare, RMS) 0.25 is closer on these scenes: 0.75 blurs small
// particles and thin plot lines that MSAA keeps sharp.
constexpr float kSubpix = 0.25f;
// Steps of the walk along an edge, px. Whole pixels (FXAA 3.11 steps by 1.5,
// 2, 4 ... on bilinear reads); here the two rows either side are averaged.
constexpr int kSteps[] = {1, 1, 2, 2, 4, 8};

/// Pixels at least this far from the border need no clamping (the walk's reach + 1).
constexpr int kMargin = 20;

/// The frame; `Clamp` = false for pixels kMargin or more from the border.
template <bool Clamp>
struct Frame {
  const std::uint8_t* rgba;
  const std::uint8_t* luma;
  int w, h;
  std::size_t at(int x, int y) const {  // GL rows (y up)
    if constexpr (Clamp) return static_cast<std::size_t>(std::clamp(y, 0, h - 1)) * w + std::clamp(x, 0, w - 1);
    return static_cast<std::size_t>(y) * w + x;
  }
  float l(int x, int y) const { return luma[at(x, y)] * (1.0f / 255); }  // 0..1
  const std::uint8_t* px(int x, int y) const { return rgba + at(x, y) * 4; }
  bool marked_near(int x, int y) const {
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        if (px(x + dx, y + dy)[3] != 255) return true;
    return false;
  }
};

/// The edge test of FXAA on 16 pixels at once: `m` and its four neighbours'
/// luma (0..255); true where the local contrast is an edge. GCC's vector
/// extensions: SSE2's byte min/max, no per-pixel branch.
using U8x16 = std::uint8_t __attribute__((vector_size(16)));
using U16x16 = std::uint16_t __attribute__((vector_size(32)));
U8x16 vmax(U8x16 a, U8x16 b) { return a > b ? a : b; }
U8x16 vmin(U8x16 a, U8x16 b) { return a < b ? a : b; }
U8x16 edge16(U8x16 m, U8x16 l, U8x16 r, U8x16 u, U8x16 d) {
  const U8x16 hi = vmax(vmax(vmax(m, l), vmax(r, u)), d), lo = vmin(vmin(vmin(m, l), vmin(r, u)), d);
  const U16x16 range = __builtin_convertvector(hi - lo, U16x16), h = __builtin_convertvector(hi, U16x16);
  constexpr std::uint16_t kMin = kEdgeThresholdMin * 255, kRel = kEdgeThreshold * 1024;
  const U16x16 limit = (h * kRel) >> 10;
  const U16x16 edge = range >= (limit > kMin ? limit : kMin);  // all ones where true
  return __builtin_convertvector(edge, U8x16);
}

/// The blend of pixel (x, y) towards its neighbour (x + ax, y + ay): 0 = keep.
/// Called where edge16 found an edge.
template <bool Clamp>
float blend(const Frame<Clamp>& f, int x, int y, int& ax, int& ay) {
  const float m = f.l(x, y), n = f.l(x, y + 1), s = f.l(x, y - 1), e = f.l(x + 1, y), w = f.l(x - 1, y);
  const float range = std::max({m, n, s, e, w}) - std::min({m, n, s, e, w});
  if (range <= 0 || f.marked_near(x, y)) return 0;
  const float nw = f.l(x - 1, y + 1), ne = f.l(x + 1, y + 1), sw = f.l(x - 1, y - 1), se = f.l(x + 1, y - 1);

  // Sub-pixel aliasing: how far the centre is from its 3x3 low-pass.
  const float lowpass = (2 * (n + s + e + w) + (nw + ne + sw + se)) / 12;
  float sub = std::clamp(std::abs(lowpass - m) / range, 0.0f, 1.0f);
  sub = (-2 * sub + 3) * sub * sub;
  const float sub_offset = sub * sub * kSubpix;

  // A horizontal edge has N and S across it, a vertical one E and W.
  const float edge_h = std::abs(nw + sw - 2 * w) + 2 * std::abs(n + s - 2 * m) + std::abs(ne + se - 2 * e);
  const float edge_v = std::abs(nw + ne - 2 * n) + 2 * std::abs(w + e - 2 * m) + std::abs(sw + se - 2 * s);
  const bool horizontal = edge_h >= edge_v;
  const float l_neg = horizontal ? s : w, l_pos = horizontal ? n : e;
  const float g_neg = std::abs(l_neg - m), g_pos = std::abs(l_pos - m);
  const int sign = g_pos >= g_neg ? 1 : -1;  // across, towards the steeper side
  ax = horizontal ? 0 : sign;
  ay = horizontal ? sign : 0;
  const float avg = 0.5f * ((sign > 0 ? l_pos : l_neg) + m);
  const float threshold = 0.25f * std::max(g_neg, g_pos);

  // Walk both ways along the edge until the pixel pair across it leaves the
  // pair's average here: the edge ends there.
  const int lx = horizontal ? 1 : 0, ly = horizontal ? 0 : 1;
  auto pair = [&](int d) { return 0.5f * (f.l(x + lx * d, y + ly * d) + f.l(x + lx * d + ax, y + ly * d + ay)) - avg; };
  int dist_n = 0, dist_p = 0;
  float end_n = 0, end_p = 0;
  bool done_n = false, done_p = false;
  for (int step : kSteps) {
    if (!done_n) {
      dist_n += step;
      end_n = pair(-dist_n);
      done_n = std::abs(end_n) >= threshold;
    }
    if (!done_p) {
      dist_p += step;
      end_p = pair(dist_p);
      done_p = std::abs(end_p) >= threshold;
    }
    if (done_n && done_p) break;
  }
  // Blend only when the nearer end turns the way the centre does; else the
  // pixel lies on the edge's straight run, not at a step of it.
  const bool nearer_n = dist_n < dist_p;
  const bool good = ((nearer_n ? end_n : end_p) < 0) != (m - avg < 0);
  const float edge_offset = good ? 0.5f - static_cast<float>(std::min(dist_n, dist_p)) / (dist_n + dist_p) : 0.0f;
  return std::max(edge_offset, sub_offset);
}

}  // namespace

void rgba_row_to_rgb(const std::uint8_t* src, int width, std::uint8_t* dst) {
  int x = 0;
  // Four pixels at a time as three 32-bit words (a byte loop is ~5x slower).
  if constexpr (std::endian::native == std::endian::little) {
    for (; x + 4 <= width; x += 4, src += 16, dst += 12) {
      std::uint32_t p[4];
      std::memcpy(p, src, sizeof p);
      const std::uint32_t out[3] = {(p[0] & 0xFFFFFFu) | (p[1] << 24), ((p[1] >> 8) & 0xFFFFu) | (p[2] << 16),
                                    ((p[2] >> 16) & 0xFFu) | (p[3] << 8)};
      std::memcpy(dst, out, sizeof out);
    }
  }
  for (; x < width; ++x, src += 4, dst += 3) dst[0] = src[0], dst[1] = src[1], dst[2] = src[2];
}

namespace {

// Row y's edge mask: nonzero where the luma contrast calls for a blend
// (16 pixels at a time; the two end pixels read their clamped neighbours).
void edge_row(const Frame<true>& f, int y, std::uint8_t* edge) {
  const int width = f.w, height = f.h;
  const std::uint8_t* row = f.luma + std::size_t(y) * width;
  const std::uint8_t* up = f.luma + std::size_t(std::min(y + 1, height - 1)) * width;
  const std::uint8_t* down = f.luma + std::size_t(std::max(y - 1, 0)) * width;
  auto load = [](const std::uint8_t* p) {
    U8x16 v;
    std::memcpy(&v, p, sizeof v);
    return v;
  };
  int x = 1;
  for (; x + 17 <= width; x += 16) {
    const U8x16 e = edge16(load(row + x), load(row + x - 1), load(row + x + 1), load(up + x), load(down + x));
    std::memcpy(edge + x, &e, sizeof e);
  }
  for (int xx : {0, width - 1})
    edge[xx] = edge16(U8x16{} + row[xx], U8x16{} + row[std::max(xx - 1, 0)], U8x16{} + row[std::min(xx + 1, width - 1)],
                      U8x16{} + up[xx], U8x16{} + down[xx])[0];
  for (; x < width - 1; ++x)
    edge[x] = edge16(U8x16{} + row[x], U8x16{} + row[x - 1], U8x16{} + row[x + 1], U8x16{} + up[x], U8x16{} + down[x])[0];
}

// Row y out (flipped: GL's rows run bottom-up): the input's colours, each edge
// pixel blended towards its neighbour across the edge (`inner`: no clamping,
// for pixels kMargin or more from the border).
void blend_row(const Frame<true>& f, const Frame<false>& inner, int y, const std::uint8_t* edge, io::Image& out) {
  const int width = f.w, height = f.h;
  const std::uint8_t* src = f.rgba + std::size_t(y) * width * 4;
  std::uint8_t* dst = out.rgb.data() + static_cast<std::size_t>(height - 1 - y) * width * 3;
  rgba_row_to_rgb(src, width, dst);
  const bool inner_row = y >= kMargin && y < height - kMargin;
  for (int i = 0; i < width; ++i) {
    if (!edge[i]) continue;
    int ax = 0, ay = 0;
    const float t = inner_row && i >= kMargin && i < width - kMargin ? blend(inner, i, y, ax, ay) : blend(f, i, y, ax, ay);
    if (t <= 0) continue;
    const std::uint8_t* a = src + 4 * i;
    const std::uint8_t* b = f.px(i + ax, y + ay);
    for (int c = 0; c < 3; ++c) dst[3 * i + c] = static_cast<std::uint8_t>(std::lround(a[c] + (b[c] - a[c]) * t));
  }
}

}  // namespace

void Fxaa::apply(const std::uint8_t* rgba, int width, int height, io::Image& out, int threads) {
  const std::size_t n = static_cast<std::size_t>(width) * height;
  luma_.resize(n);
  out.width = width;
  out.height = height;
  out.rgb.resize(n * 3);
  const Frame<true> f{rgba, luma_.data(), width, height};
  const Frame<false> inner{rgba, luma_.data(), width, height};
  // Rows [y0, y1): luma first, then the pixels (which read luma one row beyond).
  auto luma_rows = [&](int y0, int y1) {
    for (std::size_t i = std::size_t(y0) * width; i < std::size_t(y1) * width; ++i) {
      const std::uint8_t* p = rgba + 4 * i;  // Rec. 601 weights in 1/256
      luma_[i] = static_cast<std::uint8_t>((77 * p[0] + 150 * p[1] + 29 * p[2] + 128) >> 8);
    }
  };
  auto pixel_rows = [&](int y0, int y1) {
    std::vector<std::uint8_t> edge(static_cast<std::size_t>(width));
    for (int y = y0; y < y1; ++y) {
      edge_row(f, y, edge.data());
      blend_row(f, inner, y, edge.data(), out);
    }
  };
  // Two halves on two threads (the GL threads are idle now); each pixel
  // depends only on the input, so the bytes do not depend on the split.
  if (threads < 2) {
    luma_rows(0, height);
    pixel_rows(0, height);
    return;
  }
  const int mid = height / 2;
  {
    std::jthread other([&] { luma_rows(mid, height); });
    luma_rows(0, mid);
  }
  std::jthread other([&] { pixel_rows(mid, height); });
  pixel_rows(0, mid);
}

void finish_frame(const RawFrame& raw, io::Image& out, Fxaa& fxaa, int threads) {
  if (raw.fxaa) {
    fxaa.apply(raw.rgba.data(), raw.width, raw.height, out, threads);
    return;
  }
  const std::size_t w = static_cast<std::size_t>(raw.width);
  out.width = raw.width;
  out.height = raw.height;
  out.rgb.resize(w * 3 * raw.height);
  // GL's origin is the bottom-left corner; images are stored top-down.
  for (int y = 0; y < raw.height; ++y)
    rgba_row_to_rgb(raw.rgba.data() + w * 4 * (raw.height - 1 - y), raw.width, out.rgb.data() + w * 3 * y);
}

}  // namespace tumble::render
