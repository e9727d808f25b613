// Google Benchmark: the golden-image comparison on a 720p pair
// (target: under 10 ms per compare, all figures including the connected
// regions and the windowed mean).
#include <benchmark/benchmark.h>

#include <cstdint>
#include <random>

#include "golden/compare.hpp"

namespace {

tumble::io::Image gradient(int w, int h) {
  tumble::io::Image img{w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h * 3)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int ch = 0; ch < 3; ++ch)
        img.rgb[(static_cast<std::size_t>(y) * w + x) * 3 + ch] = static_cast<std::uint8_t>((x + 2 * y + 40 * ch) % 200 + 20);
  return img;
}

/// state.range(0): percent of pixels changed by up to ±20 levels (0 = identical
/// images; 2 = typical noise; 50 = a worst case with many regions).
void BM_Compare720p(benchmark::State& st) {
  const auto a = gradient(1280, 720);
  auto b = a;
  std::mt19937 rng(16);
  const std::size_t n = static_cast<std::size_t>(1280) * 720;
  const std::size_t changed = n * static_cast<std::size_t>(st.range(0)) / 100;
  for (std::size_t i = 0; i < changed; ++i) {
    const std::size_t p = rng() % n;
    b.rgb[p * 3] = static_cast<std::uint8_t>(int(b.rgb[p * 3]) + static_cast<int>(rng() % 41) - 20);
  }
  for (auto _ : st) {
    auto c = tumble::golden::compare_images(a, b);
    benchmark::DoNotOptimize(c.window_mean);
  }
}
BENCHMARK(BM_Compare720p)->Arg(0)->Arg(2)->Arg(50)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
