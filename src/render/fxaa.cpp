#include "render/fxaa.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <thread>

namespace tumble::render {
namespace {

constexpr float kEdgeThreshold = 0.166f;     // contrast, relative to the local max, that is an edge
constexpr float kEdgeThresholdMin = 0.0833f; // darker contrast than this is left alone (3.11 defaults)
constexpr float kSubpix = 0.75f;             // strength of the sub-pixel smoothing
// Steps of the walk along an edge, px. Whole pixels (FXAA 3.11 steps by 1.5,
// 2, 4 ... on bilinear reads); here the two rows either side are averaged.
constexpr int kSteps[] = {1, 1, 2, 2, 4, 8};

struct Frame {
  const std::uint8_t* rgba;
  const float* luma;
  int w, h;
  float l(int x, int y) const {  // clamped to the frame, GL rows (y up)
    return luma[static_cast<std::size_t>(std::clamp(y, 0, h - 1)) * w + std::clamp(x, 0, w - 1)];
  }
  const std::uint8_t* px(int x, int y) const {
    return rgba + (static_cast<std::size_t>(std::clamp(y, 0, h - 1)) * w + std::clamp(x, 0, w - 1)) * 4;
  }
  bool marked_near(int x, int y) const {
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        if (px(x + dx, y + dy)[3] != 255) return true;
    return false;
  }
};

/// The blend of pixel (x, y) towards its neighbour (x + ax, y + ay): 0 = keep.
float blend(const Frame& f, int x, int y, int& ax, int& ay) {
  const float m = f.l(x, y), n = f.l(x, y + 1), s = f.l(x, y - 1), e = f.l(x + 1, y), w = f.l(x - 1, y);
  const float hi = std::max({m, n, s, e, w});
  const float range = hi - std::min({m, n, s, e, w});
  if (range < std::max(kEdgeThresholdMin, hi * kEdgeThreshold)) return 0;
  if (f.marked_near(x, y)) return 0;
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

void Fxaa::apply(const std::uint8_t* rgba, int width, int height, io::Image& out) {
  const std::size_t n = static_cast<std::size_t>(width) * height;
  luma_.resize(n);
  out.width = width;
  out.height = height;
  out.rgb.resize(n * 3);
  const Frame f{rgba, luma_.data(), width, height};
  // Rows [y0, y1): luma first, then the pixels (which read luma one row beyond).
  auto luma_rows = [&](int y0, int y1) {
    for (std::size_t i = std::size_t(y0) * width; i < std::size_t(y1) * width; ++i) {
      const std::uint8_t* p = rgba + 4 * i;
      luma_[i] = (0.299f * p[0] + 0.587f * p[1] + 0.114f * p[2]) * (1.0f / 255);
    }
  };
  auto pixel_rows = [&](int y0, int y1) {
    for (int y = y0; y < y1; ++y) {
      const float* row = f.luma + std::size_t(y) * width;
      const float* up = f.luma + std::size_t(std::min(y + 1, height - 1)) * width;
      const float* down = f.luma + std::size_t(std::max(y - 1, 0)) * width;
      const std::uint8_t* src = rgba + std::size_t(y) * width * 4;
      std::uint8_t* dst = out.rgb.data() + static_cast<std::size_t>(height - 1 - y) * width * 3;
      for (int x = 0; x < width; ++x, src += 4, dst += 3) {
        // The early out of blend(), inline and branch-free: most pixels are no edge.
        const int xl = x > 0 ? x - 1 : 0, xr = x + 1 < width ? x + 1 : x;
        const float m = row[x], l = row[xl], r = row[xr], u = up[x], d = down[x];
        const float hi = std::max(std::max(std::max(m, l), std::max(r, u)), d);
        const float lo = std::min(std::min(std::min(m, l), std::min(r, u)), d);
        int ax = 0, ay = 0;
        const float t = hi - lo < std::max(kEdgeThresholdMin, hi * kEdgeThreshold) ? 0.0f : blend(f, x, y, ax, ay);
        if (t <= 0) {
          dst[0] = src[0], dst[1] = src[1], dst[2] = src[2];
          continue;
        }
        const std::uint8_t* b = f.px(x + ax, y + ay);
        for (int c = 0; c < 3; ++c) dst[c] = static_cast<std::uint8_t>(std::lround(src[c] + (b[c] - src[c]) * t));
      }
    }
  };
  // Two halves on two threads (the GL threads are idle now); each pixel
  // depends only on the input, so the bytes do not depend on the split.
  const int mid = height / 2;
  {
    std::jthread other([&] { luma_rows(mid, height); });
    luma_rows(0, mid);
  }
  std::jthread other([&] { pixel_rows(mid, height); });
  pixel_rows(0, mid);
}

}  // namespace tumble::render
