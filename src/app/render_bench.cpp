#include "app/render_bench.hpp"

#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "app/render_job.hpp"
#include "app/video.hpp"
#include "app/video_stream.hpp"
#include "io/atomic_file.hpp"
#include "io/frame_files.hpp"
#include "render/frame_encoder.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"

namespace tumble::app {

namespace {
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }
/// CPU seconds (user + system) of this process and its waited-for children
/// (ffmpeg): less disturbed than wall time when other work shares the cores.
double cpu_seconds() {
  double s = 0;
  for (int who : {RUSAGE_SELF, RUSAGE_CHILDREN}) {
    rusage u{};
    ::getrusage(who, &u);
    s += u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
  }
  return s;
}
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
  // An earlier, longer bench's frames would be read into this one's video.
  for (const auto& f : std::filesystem::directory_iterator(out_dir))
    if (io::is_frame_file(f.path().filename().string())) std::filesystem::remove(f.path());
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
  const double c0 = cpu_seconds();
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
  const double total = seconds_since(t0), total_cpu = cpu_seconds() - c0;

  // The video, both ways, from the same frames: PNG files read back by ffmpeg
  // (the end-to-end run above, then the encode), and raw frames piped to it.
  if (ffmpeg_available()) {
    const auto tv = Clock::now();
    const double cv = cpu_seconds();
    const VideoResult v = encode_video(out_dir, static_cast<int>(std::lround(fps)), VideoFormat::mp4, 18,
                                       out_dir / "png_path.mp4");
    if (v.ok()) r.png_video_fps = frames / (total + seconds_since(tv));
    if (v.ok()) r.png_video_cpu_ms = 1000 * (total_cpu + cpu_seconds() - cv) / frames;
    const auto ts = Clock::now();
    const double cs = cpu_seconds();
    {
      const std::vector<Run> runs3 = simulate_runs(s, frames, fps);
      const FrameBuilder builder3(s, runs3, fps, 1280, 720);
      VideoStream stream(1280, 720, static_cast<int>(std::lround(fps)), VideoFormat::mp4, 18, out_dir / "stream_path.mp4");
      io::Image img;
      for (long k = 0; k < frames && stream.running() && !stream.broken(); ++k) {
        renderer.render(builder3.build(k), img);
        stream.write(img, {});
      }
      if (stream.finish().ok()) {
        r.stream_video_fps = frames / seconds_since(ts);
        r.stream_video_cpu_ms = 1000 * (cpu_seconds() - cs) / frames;
      }
    }
  }
  r.end_to_end_fps = frames / total;
  r.encode_only_fps = frames / encode;
  r.render_ms = 1000 * render_s / frames;

  char buf[1024];
  std::snprintf(buf, sizeof buf,
                "# tumble bench --render\n\nScene `%s`, %ld frames, 1280x720, 4x MSAA, %s (%s).\n\n"
                "| measure | value |\n|---|---|\n| end to end | %.1f frames/s |\n| encode-only limit (2 threads) | "
                "%.1f frames/s |\n| end-to-end / encode-only | %.2f |\n| build + draw + read back, mean | %.1f ms/frame |\n"
                "| H.264 video via PNG files (render, then ffmpeg reads them) | %.1f frames/s, CPU %.1f ms/frame |\n"
                "| H.264 video, raw frames piped to ffmpeg (--frames-out none) | %.1f frames/s, CPU %.1f ms/frame |\n",
                scene_path.string().c_str(), frames, ctx->renderer().c_str(), ctx->version().c_str(),
                r.end_to_end_fps, r.encode_only_fps, r.end_to_end_fps / r.encode_only_fps, r.render_ms, r.png_video_fps,
                r.png_video_cpu_ms, r.stream_video_fps, r.stream_video_cpu_ms);
  io::atomic_write_file(out_dir / "render.md", buf);
  log << buf;
  return r;
}

}  // namespace tumble::app
