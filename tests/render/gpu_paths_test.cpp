// The GPU paths on whatever GL this machine has (llvmpipe here; the same
// code runs on a hardware GPU): overlapped read-back gives render()'s bytes
// in frame order, and GL FXAA stays within the golden tolerances of the CPU
// FXAA that the goldens hold (on llvmpipe: its bytes exactly).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/image.hpp"
#include "render/fxaa.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"
#include "gl_test.hpp"
#include "test_scenes.hpp"

namespace tumble::render {
namespace {

class GpuPathsTest : public test::GlTest {};

/// The showcase on a darker background for each `k`: frames that differ.
viz::DrawList frame(int k) {
  viz::DrawList dl = test::showcase();
  dl.background.r -= 0.1f * k;
  return dl;
}

TEST_F(GpuPathsTest, OverlappedReadbackGivesRenderBytesInOrder) {
  Renderer plain(*context_, 200, 150, scene::Antialias::fxaa), overlapped(*context_, 200, 150, scene::Antialias::fxaa);
  plain.set_gpu_paths({});
  overlapped.set_gpu_paths({true, false});
  std::vector<io::Image> expected, got(4);
  for (int k = 0; k < 4; ++k) expected.push_back(plain.render(frame(k)));
  ASSERT_FALSE(expected[0].rgb == expected[1].rgb);  // the frames tell apart
  Fxaa fxaa;
  RawFrame raw;
  int handed = 0;
  auto take = [&] {
    ASSERT_GE(raw.index, 0);
    ASSERT_LT(raw.index, 4);
    finish_frame(raw, got[static_cast<std::size_t>(raw.index)], fxaa);
    ++handed;
  };
  for (int k = 0; k < 4; ++k) {
    const bool ready = overlapped.render_overlapped(frame(k), k, raw);
    EXPECT_EQ(ready, k > 0) << "one frame late";
    if (ready) {
      EXPECT_EQ(raw.index, k - 1);
      take();
    }
  }
  ASSERT_TRUE(overlapped.finish_overlapped(raw));
  EXPECT_EQ(raw.index, 3);
  take();
  EXPECT_FALSE(overlapped.finish_overlapped(raw));
  EXPECT_EQ(handed, 4);
  for (int k = 0; k < 4; ++k) EXPECT_TRUE(got[k].rgb == expected[k].rgb) << "frame " << k;
}

TEST_F(GpuPathsTest, WithoutOverlapEachFrameComesBackAtOnce) {
  Renderer r(*context_, 64, 48, scene::Antialias::none);
  r.set_gpu_paths({});
  RawFrame raw;
  ASSERT_TRUE(r.render_overlapped(frame(0), 7, raw));
  EXPECT_EQ(raw.index, 7);
  EXPECT_FALSE(r.finish_overlapped(raw));
}

/// Pixels whose largest channel differs by more than 8 levels (the golden
/// tolerance's max_delta), and the largest difference.
std::pair<long, int> differing(const io::Image& a, const io::Image& b) {
  long over = 0;
  int worst = 0;
  for (std::size_t i = 0; i + 2 < a.rgb.size(); i += 3) {
    int d = 0;
    for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a.rgb[i + c]) - int(b.rgb[i + c])));
    over += d > 8;
    worst = std::max(worst, d);
  }
  return {over, worst};
}

TEST_F(GpuPathsTest, GlFxaaMatchesCpuFxaaWithinGoldenTolerance) {
  constexpr int kW = 320, kH = 240;
  Renderer cpu(*context_, kW, kH, scene::Antialias::fxaa), gpu(*context_, kW, kH, scene::Antialias::fxaa),
      none(*context_, kW, kH, scene::Antialias::none);
  cpu.set_gpu_paths({});
  gpu.set_gpu_paths({false, true});
  const viz::DrawList dl = test::showcase();
  const io::Image c = cpu.render(dl), g = gpu.render(dl), n = none.render(dl);
  ASSERT_EQ(g.rgb.size(), c.rgb.size());
  const auto [over, worst] = differing(g, c);
  EXPECT_LE(over, static_cast<long>(0.0005 * kW * kH)) << "largest difference " << worst;
  // On a software rasteriser, IEEE floats without contraction as the CPU's:
  // the same bytes (a hardware GPU may round its divisions differently).
  if (is_software_renderer(context_->renderer())) {
    EXPECT_EQ(worst, 0);
  }
  // The pass ran: GL FXAA changed what the plain frame has.
  EXPECT_FALSE(g.rgb == n.rgb);
  RecordProperty("gl_fxaa_max_delta", worst);
  RecordProperty("gl_fxaa_pixels_over_8", static_cast<int>(over));
  long any = 0;
  for (std::size_t i = 0; i < c.rgb.size(); i += 3) any += c.rgb[i] != g.rgb[i] || c.rgb[i + 1] != g.rgb[i + 1] || c.rgb[i + 2] != g.rgb[i + 2];
  RecordProperty("gl_fxaa_pixels_different", static_cast<int>(any));
}

}  // namespace
}  // namespace tumble::render
