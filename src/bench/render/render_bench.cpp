#include "bench/render/render_bench.hpp"

#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "run/frame_renderer.hpp"
#include "compose/frame_builder.hpp"
#include "run/frame_range.hpp"
#include "run/render_stream.hpp"
#include "run/video.hpp"
#include "run/video_stream.hpp"
#include "golden/compare.hpp"
#include "io/atomic_file.hpp"
#include "io/frame_files.hpp"
#include "render/frame_encoder.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"
#include "render/worker_threads.hpp"

namespace tumble::bench {

using namespace tumble::run;  // the render pipeline this measures

namespace {
using Clock = std::chrono::steady_clock;
constexpr int kW = 1280, kH = 720;
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

struct EndToEnd {
  double seconds = 0, cpu_seconds = 0, render_seconds = 0;
};

/// As `tumble render` does it: simulation, frame building, drawing, read
/// back, then on the encoder's threads FXAA, PNG encode and write, timed together.
EndToEnd end_to_end(const scene::Scene& s, long frames, render::Renderer& renderer,
                    const std::filesystem::path& out_dir, int jobs) {
  EndToEnd r;
  const auto t0 = Clock::now();
  const double c0 = cpu_seconds();
  {
    const std::vector<scene::Run> runs = scene::simulate_runs(s, frames, s.render.output.fps);
    const compose::FrameBuilder builder(s, runs, s.render.output.fps, kW, kH);
    render::FrameEncoder encoder(jobs);
    render::RawFrame raw;
    auto submit = [&] {
      const std::filesystem::path path = io::frame_path(out_dir, raw.index);
      encoder.submit(path, std::move(raw));
      raw = encoder.recycle_raw();
    };
    for (long k = 0; k < frames; ++k) {
      const auto tr = Clock::now();
      const bool ready = renderer.render_overlapped(builder.build(k), k, raw);
      r.render_seconds += seconds_since(tr);
      if (ready) submit();
    }
    if (renderer.finish_overlapped(raw)) submit();
    encoder.flush();
  }
  r.seconds = seconds_since(t0);
  r.cpu_seconds = cpu_seconds() - c0;
  return r;
}

/// FXAA and no anti-aliasing against 4x MSAA at three frames (a quarter, half
/// and three quarters through the scene).
AaQuality measure_quality(render::GlContext& ctx, const std::filesystem::path& path) {
  scene::Scene s = scene::load_scene(path);
  const long count = scene::frame_clock(s, s.render.output.fps).count();
  const std::vector<long> ks = {count / 4, count / 2, 3 * count / 4};
  const SceneFrames frames(s, ks.back());
  auto at = [&](scene::Antialias aa) {
    scene::FrameSettings f;
    f.width = kW;
    f.height = kH;
    f.aa = aa;
    f.msaa = 4;
    return frames.render(ctx, ks, f);
  };
  const auto reference = at(scene::Antialias::msaa);
  const auto fxaa = at(scene::Antialias::fxaa);
  const auto none = at(scene::Antialias::none);
  AaQuality q;
  q.scene = path.filename().string();
  q.frames = static_cast<int>(ks.size());
  for (std::size_t i = 0; i < ks.size(); ++i) {
    const golden::Comparison f = golden::compare_images(fxaa[i], reference[i]);
    const golden::Comparison n = golden::compare_images(none[i], reference[i]);
    q.fxaa_rms += f.rms / ks.size(), q.fxaa_over += f.fraction / ks.size();
    q.none_rms += n.rms / ks.size(), q.none_over += n.fraction / ks.size();
  }
  return q;
}

/// A video row's value: frames/s and CPU, or why there is none.
std::string video_cell(const VideoRow& v) {
  if (!v.error.empty()) return v.error;
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.1f frames/s, CPU %.1f ms/frame", v.fps, v.cpu_ms);
  return buf;
}

std::string markdown(const RenderBenchResult& r, const std::string& scene) {
  char buf[2048];
  std::snprintf(
      buf, sizeof buf,
      "Scene `%s`, %ld frames, 1280x720, %s; %s; %d frame encoder threads; \"high\" quality is %s. End to "
      "end: best of two runs each, FXAA and MSAA interleaved; CPU is user + system time of all threads.\n\n"
      "| measure | value |\n|---|---|\n| end to end, high quality (FXAA) | %.1f frames/s, CPU %.1f ms/frame |\n"
      "| encode-only limit (%d threads) | %.1f frames/s |\n| end-to-end / encode-only | %.2f |\n"
      "| build + draw + read back, mean (FXAA: %s) | %.1f ms/frame |\n"
      "| end to end, 4x MSAA | %.1f frames/s, CPU %.1f ms/frame |\n"
      "| build + draw + read back, mean (4x MSAA) | %.1f ms/frame |\n"
      "| end to end, FXAA, the other GPU paths (%s) | %.1f frames/s, CPU %.1f ms/frame |\n",
      scene.c_str(), r.frames, r.gl.c_str(), r.hardware_gpu ? "a hardware GPU" : "not a hardware GPU", r.threads,
      r.paths.c_str(), r.end_to_end_fps, r.cpu_ms, r.threads, r.encode_only_fps, r.end_to_end_fps / r.encode_only_fps,
      r.gl_fxaa ? "a GL pass" : "on the encoder threads", r.render_ms, r.msaa_end_to_end_fps, r.msaa_cpu_ms,
      r.msaa_render_ms, r.other_paths.c_str(), r.other_paths_fps, r.other_paths_cpu_ms);
  std::string md = buf;
  md += "| H.264 video via PNG files (render, then ffmpeg reads them; " + r.video_encoder + ", all cores) | " +
        video_cell(r.png_video) + " |\n";
  md += "| H.264 video, raw frames piped to ffmpeg (--frames-out none; " + r.video_encoder + r.stream_threads + ") | " +
        video_cell(r.stream_video) + " |\n";
  if (r.quality.empty()) return md;
  md += "\nAnti-aliasing against 4x MSAA (the reference), 1280x720, mean over frames at 1/4, 1/2 and 3/4 of each "
        "scene: RMS difference in 0..255 levels, and the share of pixels off by more than 8 levels.\n\n"
        "| scene | FXAA: RMS | FXAA: pixels > 8 | no AA: RMS | no AA: pixels > 8 |\n|---|---|---|---|---|\n";
  for (const AaQuality& q : r.quality) {
    std::snprintf(buf, sizeof buf, "| %s | %.2f | %.2f%% | %.2f | %.2f%% |\n", q.scene.c_str(), q.fxaa_rms,
                  100 * q.fxaa_over, q.none_rms, 100 * q.none_over);
    md += buf;
  }
  return md;
}

}  // namespace

namespace {

/// The video made both ways from the same frames: PNG files read back by
/// ffmpeg (the end-to-end run `e`, then the encode), and raw frames piped to it.
void measure_video(const scene::Scene& s, long frames, render::Renderer& high, const EndToEnd& e,
                   const VideoEncoder& encoder, const std::filesystem::path& out_dir, RenderBenchResult& r) {
  const int fps = static_cast<int>(std::lround(s.render.output.fps));
  if (!ffmpeg_available()) {
    r.png_video.error = r.stream_video.error = kMissingFfmpeg;
    return;
  }
  const auto tv = Clock::now();
  const double cv = cpu_seconds();
  const VideoResult v = encode_video(out_dir, fps, VideoFormat::mp4, 18, out_dir / "png_path.mp4", {}, {}, encoder);
  if (v.ok()) {
    r.png_video.fps = frames / (e.seconds + seconds_since(tv));
    r.png_video.cpu_ms = 1000 * (e.cpu_seconds + cpu_seconds() - cv) / frames;
  } else {
    r.png_video.error = v.message;
  }
  const auto ts = Clock::now();
  const double cs = cpu_seconds();
  const std::vector<scene::Run> runs = scene::simulate_runs(s, frames, s.render.output.fps);
  const compose::FrameBuilder builder(s, runs, s.render.output.fps, kW, kH);
  VideoStream stream(kW, kH, fps, VideoFormat::mp4, 18, out_dir / "stream_path.mp4", encoder);
  if (stream.running()) stream_frames(high, builder, frames, stream, r.threads, {});
  if (const VideoResult sv = stream.finish(); sv.ok()) {
    r.stream_video.fps = frames / seconds_since(ts);
    r.stream_video.cpu_ms = 1000 * (cpu_seconds() - cs) / frames;
  } else {
    r.stream_video.error = sv.message;
  }
}

std::string paths_name(render::GpuPaths p) {
  if (!p.overlapped_readback && !p.gl_fxaa) return "none";
  return std::string(p.overlapped_readback ? "PBO read-back" : "") + (p.overlapped_readback && p.gl_fxaa ? " + " : "") +
         (p.gl_fxaa ? "GL FXAA" : "");
}

/// Encode-only limit (frames/s): the same frames, drawn beforehand (untimed),
/// then only encoded and written by the same FrameEncoder.
double encode_only_fps(const scene::Scene& s, long frames, render::Renderer& high, const std::filesystem::path& out_dir,
                       int threads) {
  const double fps = s.render.output.fps;
  const std::vector<scene::Run> runs = scene::simulate_runs(s, frames, fps);
  const compose::FrameBuilder builder(s, runs, fps, kW, kH);
  std::vector<io::Image> kept;
  kept.reserve(static_cast<size_t>(frames));
  for (long k = 0; k < frames; ++k) kept.push_back(high.render(builder.build(k)));
  const auto t1 = Clock::now();
  {
    render::FrameEncoder encoder(threads);
    for (long k = 0; k < frames; ++k) encoder.submit(io::frame_path(out_dir, k), std::move(kept[static_cast<size_t>(k)]));
    encoder.flush();
  }
  return frames / seconds_since(t1);
}

/// The three renderers end to end, interleaved, best of two each: a load that
/// comes and goes (a shared machine) then favours neither. The last FXAA run's
/// frames feed the PNG video. Returns the FXAA run's figures.
EndToEnd measure_end_to_end(const scene::Scene& s, long frames, render::Renderer& high, render::Renderer& msaa,
                            render::Renderer& other, const std::filesystem::path& out_dir, RenderBenchResult& r) {
  EndToEnd m, e, o;
  for (int rep = 0; rep < 2; ++rep) {
    const EndToEnd oi = end_to_end(s, frames, other, out_dir, r.threads);
    const EndToEnd mi = end_to_end(s, frames, msaa, out_dir, r.threads);
    const EndToEnd ei = end_to_end(s, frames, high, out_dir, r.threads);
    if (rep == 0 || mi.seconds < m.seconds) m = mi;
    if (rep == 0 || ei.seconds < e.seconds) e = ei;
    if (rep == 0 || oi.seconds < o.seconds) o = oi;
  }
  r.msaa_end_to_end_fps = frames / m.seconds;
  r.msaa_render_ms = 1000 * m.render_seconds / frames;
  r.msaa_cpu_ms = 1000 * m.cpu_seconds / frames;
  r.end_to_end_fps = frames / e.seconds;
  r.render_ms = 1000 * e.render_seconds / frames;
  r.cpu_ms = 1000 * e.cpu_seconds / frames;
  r.other_paths_fps = frames / o.seconds;
  r.other_paths_cpu_ms = 1000 * o.cpu_seconds / frames;
  return e;
}

}  // namespace

RenderBenchResult run_render_bench(const std::filesystem::path& scene_path, long frames,
                                   const std::filesystem::path& out_dir, std::ostream& log,
                                   const std::vector<std::filesystem::path>& quality_scenes, int jobs) {
  scene::Scene s = scene::load_scene(scene_path);
  s.render.output.width = kW;
  s.render.output.height = kH;
  const double fps = s.render.output.fps;
  frames = std::min(frames, scene::frame_clock(s, fps).count());
  std::filesystem::create_directories(out_dir);
  // An earlier, longer bench's frames would be read into this one's video.
  for (const auto& f : std::filesystem::directory_iterator(out_dir))
    if (io::is_frame_file(f.path().filename().string())) std::filesystem::remove(f.path());
  auto ctx = render::create_gl_context(render::default_gl_backend());
  render::Renderer high(*ctx, kW, kH, scene::Antialias::fxaa);  // --quality high: FXAA
  render::Renderer msaa(*ctx, kW, kH, scene::Antialias::msaa, 4);
  // The GPU paths the default leaves off (on llvmpipe: both), measured too.
  render::Renderer other(*ctx, kW, kH, scene::Antialias::fxaa);
  const render::GpuPaths chosen = high.gpu_paths();
  other.set_gpu_paths({!chosen.overlapped_readback, !chosen.gl_fxaa});

  RenderBenchResult r;
  r.frames = frames;
  r.threads = render::worker_threads(jobs);
  r.gl = ctx->vendor() + ", " + ctx->renderer() + " (" + ctx->version() + "), " + ctx->display();
  r.hardware_gpu = ctx->hardware_gpu();
  r.gl_fxaa = chosen.gl_fxaa;
  r.paths = "FXAA with GPU paths: " + paths_name(chosen);
  r.other_paths = paths_name(other.gpu_paths());
  const VideoEncoder encoder = choose_video_encoder(ctx->vendor(), render::usable_cores());
  r.video_encoder = encoder.codec + " " + encoder.preset;
  r.stream_threads = encoder.threads ? ", " + std::to_string(encoder.threads) + " thread(s)" : "";
  r.encode_only_fps = encode_only_fps(s, frames, high, out_dir, r.threads);
  const EndToEnd e = measure_end_to_end(s, frames, high, msaa, other, out_dir, r);
  measure_video(s, frames, high, e, encoder, out_dir, r);
  r.quality.push_back(measure_quality(*ctx, scene_path));
  for (const auto& q : quality_scenes) r.quality.push_back(measure_quality(*ctx, q));

  r.markdown = markdown(r, scene_path.filename().string());
  io::atomic_write_file(out_dir / "render.md", "# tumble bench --render\n\n" + r.markdown);
  log << "# tumble bench --render\n\n" << r.markdown;
  return r;
}

}  // namespace tumble::bench
