// `tumble render SCENE`: frames (PNG, atomic), manifest.json and a video.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

#include "app/atomic_file.hpp"
#include "app/commands.hpp"
#include "app/progress.hpp"
#include "app/render_job.hpp"
#include "app/video.hpp"
#include "render/frame_encoder.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"

namespace tumble::app {

namespace {

namespace fs = std::filesystem;

struct RenderOptions {
  std::string scene, out_dir, frames, video, quality = "high", progress = "auto", gl;
  int width = 0, height = 0, msaa = -1;
  double fps = 0;
};

struct Quality {
  int msaa, crf;
};

Quality parse_quality(const std::string& q) {
  if (q == "low") return {0, 28};
  if (q == "medium") return {2, 23};
  if (q == "high") return {4, 18};
  throw InputError("--quality: expected low, medium or high, found '" + q + "'");
}

std::string json_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '"' || c == '\\') o += '\\';
    if (static_cast<unsigned char>(c) < 0x20) continue;
    o += c;
  }
  return o;
}

struct Manifest {
  std::string scene_path, scene_hash, method, gl_version, gl_renderer, backend, video;
  double dt = 0, fps = 0;
  int width = 0, height = 0, msaa = 0;
  long frame_count = 0, first = 0, last = -1, written = 0;
  bool complete = false;

  std::string json() const {
    std::ostringstream o;
    o << "{\n  \"tool\": \"tumble\",\n  \"version\": \"" << TUMBLE_VERSION << "\",\n"
      << "  \"scene\": \"" << json_escape(scene_path) << "\",\n  \"scene_hash\": \"" << scene_hash << "\",\n"
      << "  \"method\": \"" << json_escape(method) << "\",\n  \"dt\": " << format_double(dt) << ",\n"
      << "  \"fps\": " << format_double(fps) << ",\n  \"width\": " << width << ",\n  \"height\": " << height
      << ",\n  \"msaa\": " << msaa << ",\n  \"frame_count\": " << frame_count << ",\n  \"frames\": [" << first
      << ", " << last << "],\n  \"frames_written\": " << written << ",\n  \"gl_backend\": \"" << backend
      << "\",\n  \"gl_version\": \"" << json_escape(gl_version) << "\",\n  \"gl_renderer\": \""
      << json_escape(gl_renderer) << "\",\n  \"video\": \"" << json_escape(video) << "\",\n  \"complete\": "
      << (complete ? "true" : "false") << "\n}\n";
    return o.str();
  }
};


fs::path frame_path(const fs::path& dir, long k) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%06ld.png", k);
  return dir / name;
}

void apply_overrides(const RenderOptions& o, scene::Scene& s) {
  scene::OutputConfig& out = s.render.output;
  if (o.width) out.width = o.width;
  if (o.height) out.height = o.height;
  for (int v : {out.width, out.height})
    if (v < 16 || v > 16384) throw InputError("--width/--height: expected 16..16384 px, found " + std::to_string(v));
  if (o.fps != 0) {
    if (!(o.fps > 0) || !std::isfinite(o.fps)) throw InputError("--fps: expected a number > 0");
    out.fps = o.fps;
  }
  const Quality q = parse_quality(o.quality);
  if (o.quality != "high" || o.msaa < 0) out.msaa = std::min(out.msaa, q.msaa);
  if (o.msaa >= 0) {
    if (o.msaa != 0 && o.msaa != 2 && o.msaa != 4) throw InputError("--msaa: expected 0, 2 or 4");
    out.msaa = o.msaa;
  }
  if (!o.video.empty()) {
    if (o.video == "mp4") out.video = scene::VideoFormat::mp4;
    else if (o.video == "gif") out.video = scene::VideoFormat::gif;
    else if (o.video == "none") out.video = scene::VideoFormat::none;
    else throw InputError("--video: expected mp4, gif or none, found '" + o.video + "'");
  }
}

int run_render(const RenderOptions& o) {
  scene::Scene s = load_scene_verbose(o.scene);
  apply_overrides(o, s);
  const scene::OutputConfig& out = s.render.output;
  const double fps = out.fps;
  const long count = frame_count(s.simulation.duration, fps);
  const auto [first, last] = o.frames.empty() ? std::pair<long, long>{0, count - 1} : parse_frame_range(o.frames, count);
  const fs::path dir = o.out_dir.empty() ? fs::path("out") / s.name : fs::path(o.out_dir);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw IoError("cannot create output folder " + dir.string() + ": " + ec.message());

  const std::vector<Run> runs = simulate_runs(s, count, fps);
  const FrameBuilder builder(s, runs, fps, out.width, out.height);
  long good = count;  // frames every run could reach (single run: stop at divergence)
  if (runs.size() == 1) good = static_cast<long>(runs[0].frames.size());

  const render::GlBackend backend = o.gl.empty() ? render::default_gl_backend() : render::parse_gl_backend(o.gl);
  auto ctx = render::create_gl_context(backend);
  render::Renderer renderer(*ctx, out.width, out.height, out.msaa);

  Manifest man;
  man.scene_path = s.path.string();
  man.scene_hash = s.content_hash;
  for (const Run& r : runs) man.method += (man.method.empty() ? "" : ",") + r.label;
  man.dt = s.simulation.dt;
  man.fps = fps;
  man.width = out.width;
  man.height = out.height;
  man.msaa = renderer.samples();
  man.frame_count = count;
  man.first = first;
  man.last = last;
  man.gl_version = ctx->version();
  man.gl_renderer = ctx->renderer();
  man.backend = std::string(render::to_string(backend));
  atomic_write_file(dir / "manifest.json", man.json());

  Progress progress(last - first + 1, o.progress != "none");
  {
    render::FrameEncoder encoder(2, 4);
    for (long k = first; k <= last && k < good; ++k) {
      encoder.submit(frame_path(dir, k), renderer.render(builder.build(k)));
      man.written = k - first + 1;
      progress.update(man.written);
    }
    encoder.flush();
  }
  progress.finish();
  man.complete = man.written == last - first + 1;
  if (!man.complete) {
    atomic_write_file(dir / "manifest.json", man.json());
    std::cerr << "tumble: " << *runs[0].diverged << "\n"
              << "tumble: kept " << man.written << " frames in " << dir.string() << "\n";
    return kDiverged;
  }
  const bool full = first == 0 && last == count - 1;
  if (full && out.video != scene::VideoFormat::none) {
    const fs::path video = dir / (s.name + (out.video == scene::VideoFormat::mp4 ? ".mp4" : ".gif"));
    const std::string err = encode_video(dir, static_cast<int>(std::lround(fps)), out.video,
                                         parse_quality(o.quality).crf, video);
    if (err.empty()) man.video = video.filename().string();
    else std::cerr << "tumble: " << err << "\n";
  }
  atomic_write_file(dir / "manifest.json", man.json());
  std::cout << "rendered frames " << first << ".." << last << " of " << count << " into " << dir.string()
            << (man.video.empty() ? "" : " (video " + man.video + ")") << "\n";
  return kOk;
}

}  // namespace

void add_render_command(CLI::App& app, Action& action) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene headless to PNG frames, a manifest and a video");
  cmd->add_option("scene", o->scene, "Scene file (TOML)")->required();
  cmd->add_option("-o,--out", o->out_dir, "Output folder (default out/<scene name>)");
  cmd->add_option("--width", o->width, "Frame width, px");
  cmd->add_option("--height", o->height, "Frame height, px");
  cmd->add_option("--fps", o->fps, "Frames per second (frame k shows t = k/fps)");
  cmd->add_option("--frames", o->frames, "Render only frames A:B (inclusive); pixels equal a full run's");
  cmd->add_option("--video", o->video, "mp4, gif or none (default: the scene's [output] video)");
  cmd->add_option("--quality", o->quality, "low (no MSAA, CRF 28), medium (2x, CRF 23), high (4x, CRF 18)");
  cmd->add_option("--msaa", o->msaa, "MSAA samples 0, 2 or 4 (overrides --quality)");
  cmd->add_option("--progress", o->progress, "auto (a bar on a terminal) or none");
  cmd->add_option("--gl", o->gl, "osmesa or egl (default: env TUMBLE_GL, else osmesa)");
  cmd->callback([o, &action] { action = [o] { return run_render(*o); }; });
}

}  // namespace tumble::app
