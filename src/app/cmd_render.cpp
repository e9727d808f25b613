// `tumble render SCENE`: frames (PNG, atomic), manifest.json and a video.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "io/atomic_file.hpp"
#include "io/frame_files.hpp"
#include "app/commands.hpp"
#include "app/frame_renderer.hpp"
#include "app/progress.hpp"
#include "app/render_output.hpp"
#include "app/render_job.hpp"
#include "app/video.hpp"
#include "render/frame_encoder.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace tumble::app {

namespace {

namespace fs = std::filesystem;

struct RenderOptions {
  std::string scene, out_dir, frames, video, quality = "high", progress = "auto", gl;
  std::optional<int> width, height, msaa;
  std::optional<double> fps;
  bool resume = false, force = false;
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

/// The options that are scene keys go into the scene before it is validated,
/// so the loader's checks (sizes, frame cap, names) cover them too.
std::vector<scene::Override> scene_overrides(const RenderOptions& o) {
  std::vector<scene::Override> v;
  if (o.width) v.push_back({"--width", "output.width", static_cast<long long>(*o.width)});
  if (o.height) v.push_back({"--height", "output.height", static_cast<long long>(*o.height)});
  if (o.fps) v.push_back({"--fps", "output.fps", *o.fps});
  if (o.msaa) v.push_back({"--msaa", "output.msaa", static_cast<long long>(*o.msaa)});
  if (!o.video.empty()) v.push_back({"--video", "output.video", o.video});
  return v;
}

/// The run configuration, every option checked before any work.
struct RenderPlan {
  scene::Scene scene;
  Quality quality;
  render::GlBackend backend;
  long count;
};

RenderPlan plan_render(const RenderOptions& o) {
  const Quality q = parse_quality(o.quality);
  if (o.progress != "auto" && o.progress != "none")
    throw InputError("--progress: expected auto or none, found '" + o.progress + "'");
  const render::GlBackend backend = parse_backend_option(o.gl);
  scene::Scene s = load_scene_verbose(o.scene, scene_overrides(o));
  scene::OutputConfig& out = s.render.output;
  if (o.quality != "high" || !o.msaa) out.msaa = std::min(out.msaa, q.msaa);
  if (o.msaa) out.msaa = *o.msaa;
  const long count = scene::frame_clock(s, out.fps).count();
  return {std::move(s), q, backend, count};
}

// ---- Interruption -----------------------------------------------------------
// The one piece of global mutable state in the program, and the accepted
// exception: a signal handler may only store to a volatile sig_atomic_t. It
// holds the number of the first SIGINT/SIGTERM received (0 = none); the render
// loop polls it between frames.
volatile std::sig_atomic_t g_stop_signal = 0;

extern "C" void on_stop_signal(int sig) { g_stop_signal = sig; }

/// While alive, SIGINT and SIGTERM ask the render loop to stop after the frames
/// in flight. One-shot (SA_RESETHAND): a second Ctrl-C kills at once, which is
/// still safe because every file is written by temp file + rename.
class StopSignals {
 public:
  StopSignals() {
    g_stop_signal = 0;
    struct sigaction sa {};
    sa.sa_handler = on_stop_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESETHAND;
    ::sigaction(SIGINT, &sa, &old_int_);
    ::sigaction(SIGTERM, &sa, &old_term_);
  }
  ~StopSignals() {
    ::sigaction(SIGINT, &old_int_, nullptr);
    ::sigaction(SIGTERM, &old_term_, nullptr);
  }
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;
  int received() const { return g_stop_signal; }

 private:
  struct sigaction old_int_ {}, old_term_ {};
};

std::string quote_arg(const std::string& a) {
  if (a.find_first_of(" '\"\\$`") == std::string::npos) return a;
  std::string q = "'";
  for (char c : a) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

int run_render(const RenderOptions& o) {
  RenderPlan plan = plan_render(o);
  const scene::Scene& s = plan.scene;
  const scene::OutputConfig& out = s.render.output;
  const double fps = out.fps;
  const long count = plan.count;
  const std::pair<long, long> asked =
      o.frames.empty() ? std::pair<long, long>{0, count - 1} : parse_frame_range(o.frames, count);
  const fs::path dir = o.out_dir.empty() ? fs::path("out") / s.name : fs::path(o.out_dir);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw io::IoError("cannot create output folder '" + dir.string() + "': " + ec.message());
  if (!fs::is_directory(dir, ec)) throw io::IoError("output path '" + dir.string() + "' is not a folder");

  Manifest man;
  man.scene_path = s.path.string();
  man.scene_name = s.name;
  man.scene_hash = s.content_hash;
  {
    std::vector<std::string> labels;
    if (!s.render.compare_methods.empty())
      for (Method m : s.render.compare_methods) labels.emplace_back(method_name(m));
    else
      for (const scene::Body& b : s.bodies) {
        // auto with a tolerance: the pick follows from the scene bytes (hashed) and the tolerance.
        const std::string n = !s.simulation.method && s.simulation.tolerance
                                  ? "auto@" + format_double(*s.simulation.tolerance)
                                  : std::string(method_name(scene::resolve_method(s.simulation.method, b.model)));
        if (std::find(labels.begin(), labels.end(), n) == labels.end()) labels.push_back(n);
      }
    std::string key;
    for (const auto& l : labels) key += l + ",";
    man.settings_hash = settings_hash(s, key);
  }
  const Existing existing = inspect_output(dir, man, o.force);
  std::pair<long, long> range = asked;
  if (o.frames.empty() && o.resume && existing.resumable && existing.first >= 0 && existing.last < count &&
      existing.first <= existing.last)
    range = {existing.first, existing.last};  // continue the range that was being rendered
  const auto [first, last] = range;
  const bool resume = o.resume && existing.resumable;
  man.replacing = existing.replacing;
  if (existing.replacing)
    std::cerr << "tumble: replacing the earlier render of " << s.name << " in " << dir.string()
              << " (scene or settings changed): frames are overwritten one by one, the rest removed at the end\n";
  // A process killed mid-write leaves its temp files; they are never valid output.
  for (const fs::path& t : list_dir(dir, is_stale_temp)) remove_file(t);

  const std::vector<Run> runs = simulate_runs(s, count, fps);
  for (const Run& r : runs)
    for (const std::string& note : r.auto_notes) std::cerr << "tumble: " << note << "\n";
  const FrameBuilder builder(s, runs, fps, out.width, out.height);
  long good = count;  // frames every run could reach (single run: stop at divergence)
  if (runs.size() == 1) good = static_cast<long>(runs[0].frames.size());

  const render::GlBackend backend = plan.backend;
  auto ctx = render::create_gl_context(backend);
  render::Renderer renderer(*ctx, out.width, out.height, out.msaa);

  for (const Run& r : runs) man.method += (man.method.empty() ? "" : ",") + r.label;
  for (const Run& r : runs) man.step += (man.step.empty() ? "" : ",") + r.step_label;
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

  // From here on, files change: Ctrl-C / SIGTERM stop between frames instead
  // of killing the process, so the manifest tells what is on disk.
  const StopSignals stop;
  long drawn = 0;  // frames this run submitted (whole on disk once the encoder is flushed)
  auto on_disk = [&] {
    if (man.replacing) return drawn;  // the earlier render's frames are not ours
    long n = 0;
    for (long k = first; k <= last; ++k) n += fs::exists(io::frame_path(dir, k), ec) ? 1 : 0;
    return n;
  };
  if (resume) man.written = on_disk();
  io::atomic_write_file(dir / "manifest.json", man.json());

  Progress progress(last - first + 1, o.progress != "none");
  long skipped = 0;
  int signal = 0;
  try {
    render::FrameEncoder encoder(2, 4);
    for (long k = first; k <= last && k < good; ++k) {
      if ((signal = stop.received()) != 0) break;
      if (resume && fs::exists(io::frame_path(dir, k), ec)) {
        ++skipped;  // written whole by an earlier run (rename is atomic)
      } else {
        // Reuse a written frame's buffer: a fresh 2.7 MB image per frame costs page faults.
        io::Image img = encoder.recycle();
        renderer.render(builder.build(k), img);
        encoder.submit(io::frame_path(dir, k), std::move(img));
        ++drawn;
      }
      progress.update(k - first + 1);
    }
    encoder.flush();  // the frames in flight are finished, not dropped
  } catch (const std::runtime_error& e) {  // a frame could not be written: disk full, permissions
    man.written = on_disk();
    try {
      io::atomic_write_file(dir / "manifest.json", man.json());
    } catch (const std::exception&) {  // the disk that failed the frame may fail this too
    }
    throw io::IoError(e.what());
  }
  progress.finish();
  if (signal == 0) signal = stop.received();  // arrived during the last frames: they are whole anyway
  man.written = on_disk();
  man.complete = man.written == last - first + 1;
  if (!man.complete || signal != 0) {
    man.complete = false;
    io::atomic_write_file(dir / "manifest.json", man.json());
    if (signal != 0) {
      std::cerr << "tumble: interrupted (" << (signal == SIGINT ? "SIGINT" : "SIGTERM") << "): kept " << man.written
                << " of " << last - first + 1 << " frames in " << dir.string() << "\n"
                << "tumble: continue with: tumble render " << quote_arg(o.scene) << " -o " << quote_arg(dir.string())
                << " --resume\n";
      return 128 + signal;
    }
    std::cerr << "tumble: " << runs[0].diverged.value_or("stopped early") << "\n"
              << "tumble: kept " << man.written << " frames in " << dir.string() << "\n";
    return kDiverged;
  }
  // Every new frame exists: the earlier render's other frames can go (before
  // the encode, which would read a stale frame past the last as one of ours).
  remove_stale(dir, existing, first, last,
               out.video == scene::VideoFormat::none ? std::string() : video_file_name(s, out.video));
  man.replacing = false;
  const bool full = first == 0 && last == count - 1;
  if (full && out.video != scene::VideoFormat::none) {
    // The video is part of a complete render: until it exists the manifest says
    // "complete": false, and --resume (every frame already on disk) makes it.
    const fs::path video = dir / video_file_name(s, out.video);
    if (o.progress != "none") std::cerr << "tumble: encoding " << video.filename().string() << " from " << count << " frames\n";
    Progress encoding(count, o.progress != "none");
    const VideoResult v = encode_video(
        dir, static_cast<int>(std::lround(fps)), out.video, plan.quality.crf, video, [&] { return stop.received(); },
        [&](long n) { encoding.update(std::min(n, count)); });
    encoding.finish();
    if (!v.ok()) {
      man.complete = false;
      man.video_error = v.message;
      io::atomic_write_file(dir / "manifest.json", man.json());
      std::cerr << "tumble: " << v.message << "\n"
                << "tumble: all " << count << " frames are in " << dir.string() << "; make the video with: tumble render "
                << quote_arg(o.scene) << " -o " << quote_arg(dir.string()) << " --resume\n";
      return v.status == VideoResult::interrupted ? 128 + v.signal : kRuntimeError;
    }
    man.video = video.filename().string();
  }
  io::atomic_write_file(dir / "manifest.json", man.json());
  std::cout << "rendered frames " << first << ".." << last << " of " << count << " into " << dir.string()
            << (skipped ? " (" + std::to_string(skipped) + " already on disk)" : std::string())
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
  cmd->add_option("--fps", o->fps, "Frames per second (frame k shows t = k·time_scale/fps)");
  cmd->add_option("--frames", o->frames, "Render only frames A:B (inclusive); pixels equal a full run's");
  cmd->add_option("--video", o->video, "mp4, gif or none (default: the scene's [output] video)");
  cmd->add_option("--quality", o->quality, "low (no MSAA, CRF 28), medium (2x, CRF 23), high (4x, CRF 18)");
  cmd->add_option("--msaa", o->msaa, "MSAA samples 0, 2 or 4 (overrides --quality)");
  cmd->add_option("--progress", o->progress, "auto (a bar on a terminal) or none");
  cmd->add_option("--gl", o->gl, "osmesa or egl (default: env TUMBLE_GL, else osmesa)");
  cmd->add_flag("--resume", o->resume,
                "Continue an interrupted render in the output folder: frames already on disk are kept");
  cmd->add_flag("--force", o->force,
                "Replace another render (other scene or settings) in the output folder, removing its frames");
  cmd->callback([o, &action] { action = [o] { return run_render(*o); }; });
}

}  // namespace tumble::app
