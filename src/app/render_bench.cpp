#include "app/render_bench.hpp"

#include <chrono>
#include <cstdio>

#include "app/render_job.hpp"
#include "io/atomic_file.hpp"
#include "io/frame_files.hpp"
#include "render/frame_encoder.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"

namespace tumble::app {

namespace {
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }
}  // namespace

RenderBenchResult run_render_bench(const std::filesystem::path& scene_path, long frames,
                                   const std::filesystem::path& out_dir, std::ostream& log) {
  scene::Scene s = scene::load_scene(scene_path);
  s.render.output.width = 1280;
  s.render.output.height = 720;
  s.render.output.msaa = 4;
  const double fps = s.render.output.fps;
  frames = std::min(frames, scene::frame_clock(s, fps).count());
  std::filesystem::create_directories(out_dir);
  auto ctx = render::create_gl_context(render::default_gl_backend());
  render::Renderer renderer(*ctx, 1280, 720, 4);

  RenderBenchResult r;
  r.frames = frames;
  const std::vector<Run> runs = simulate_runs(s, frames, fps);
  const FrameBuilder builder(s, runs, fps, 1280, 720);

  // Encode-only limit: the same frames, drawn beforehand (untimed), then only
  // encoded and written by the same FrameEncoder.
  std::vector<io::Image> kept;
  kept.reserve(static_cast<size_t>(frames));
  for (long k = 0; k < frames; ++k) kept.push_back(renderer.render(builder.build(k)));
  const auto t1 = Clock::now();
  {
    render::FrameEncoder encoder(2, 4);
    for (long k = 0; k < frames; ++k) encoder.submit(io::frame_path(out_dir, k), std::move(kept[static_cast<size_t>(k)]));
    encoder.flush();
  }
  const double encode = seconds_since(t1);
  kept.clear();

  // End to end, as `tumble render` does it: simulation and frame building included.
  double render_s = 0;
  const auto t0 = Clock::now();
  {
    const std::vector<Run> runs2 = simulate_runs(s, frames, fps);
    const FrameBuilder builder2(s, runs2, fps, 1280, 720);
    render::FrameEncoder encoder(2, 4);
    for (long k = 0; k < frames; ++k) {
      const auto tr = Clock::now();
      io::Image img = encoder.recycle();
      renderer.render(builder2.build(k), img);
      render_s += seconds_since(tr);
      encoder.submit(io::frame_path(out_dir, k), std::move(img));
    }
    encoder.flush();
  }
  const double total = seconds_since(t0);
  r.end_to_end_fps = frames / total;
  r.encode_only_fps = frames / encode;
  r.render_ms = 1000 * render_s / frames;

  char buf[512];
  std::snprintf(buf, sizeof buf,
                "# tumble bench --render\n\nScene `%s`, %ld frames, 1280x720, 4x MSAA, %s (%s).\n\n"
                "| measure | value |\n|---|---|\n| end to end | %.1f frames/s |\n| encode-only limit (2 threads) | "
                "%.1f frames/s |\n| end-to-end / encode-only | %.2f |\n| build + draw + read back, mean | %.1f ms/frame |\n",
                scene_path.string().c_str(), frames, ctx->renderer().c_str(), ctx->version().c_str(),
                r.end_to_end_fps, r.encode_only_fps, r.end_to_end_fps / r.encode_only_fps, r.render_ms);
  io::atomic_write_file(out_dir / "render.md", buf);
  log << buf;
  return r;
}

}  // namespace tumble::app
