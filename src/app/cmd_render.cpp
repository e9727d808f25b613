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
#include "app/manifest_parts.hpp"
#include "app/render_job.hpp"
#include "app/render_stream.hpp"
#include "app/stop_signals.hpp"
#include "app/video.hpp"
#include "render/frame_encoder.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace tumble::app {

namespace {

namespace fs = std::filesystem;

struct RenderOptions {
  std::string scene, out_dir, frames, video, quality = "high", progress = "auto", gl, frames_out = "png", aa;
  std::optional<int> width, height, msaa;
  std::optional<double> fps;
  bool resume = false, force = false;
};

/// What --quality caps (unless --aa or --msaa say otherwise): MSAA samples
/// (0: no anti-aliasing at all) and the video's CRF. FXAA costs about as
/// much as no anti-aliasing, so medium and high keep a scene's fxaa.
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
  // --msaa N alone means what it always did: N samples, 0 none.
  if (o.msaa && o.aa.empty()) v.push_back({"--msaa", "output.aa", std::string(*o.msaa > 0 ? "msaa" : "none")});
  if (!o.aa.empty()) v.push_back({"--aa", "output.aa", o.aa});
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
  if (o.frames_out != "png" && o.frames_out != "none")
    throw InputError("--frames-out: expected png or none, found '" + o.frames_out + "'");
  const render::GlBackend backend = parse_backend_option(o.gl);
  scene::Scene s = load_scene_verbose(o.scene, scene_overrides(o));
  scene::OutputConfig& out = s.render.output;
  if (o.frames_out == "none" && out.video == scene::VideoFormat::none)
    throw InputError("--frames-out none writes only the video, and the video is none: nothing to write; "
                     "choose --video mp4 or gif");
  if (o.frames_out == "none" && !o.frames.empty())
    throw InputError("--frames-out none streams the whole video; --frames needs PNG frames (--frames-out png)");
  if (!o.msaa && o.aa.empty()) {
    if (q.msaa == 0) out.aa = scene::Antialias::none;
    out.msaa = std::min(out.msaa, q.msaa);
  }
  const long count = scene::frame_clock(s, out.fps).count();
  return {std::move(s), q, backend, count};
}

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
        const std::string n = s.simulation.automatic && s.simulation.tolerance
                                  ? "auto@" + format_number(*s.simulation.tolerance)
                                  : std::string(method_name(scene::step_config(s.simulation, b.model).method));
        if (std::find(labels.begin(), labels.end(), n) == labels.end()) labels.push_back(n);
      }
    std::string key;
    for (const auto& l : labels) key += l + ",";
    man.settings_hash = settings_hash(s, key);
  }
  // A shard (a range short of the whole render) records itself in its own
  // part, so shards running at once never overwrite each other's manifest.
  const bool shard = asked.first != 0 || asked.second != count - 1;
  const std::string own = shard ? part_manifest_name(asked.first, asked.second) : "manifest.json";
  const fs::path man_path = dir / own;
  const Existing existing = inspect_output(dir, man, own, o.force);
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
  // A shard removes only its own: the others' in-flight temp files look the same.
  for (const fs::path& t : list_dir(dir, is_stale_temp)) {
    const std::string target(io::temp_target_name(t.filename().string()));
    const long k = io::is_frame_file(target) ? std::atol(target.c_str() + 6) : -1;
    if (!shard || target == own || (k >= first && k <= last)) remove_file(t);
  }

  const std::vector<Run> runs = simulate_runs(s, count, fps);
  for (const Run& r : runs)
    for (const std::string& note : r.auto_notes) std::cerr << "tumble: " << note << "\n";
  const FrameBuilder builder(s, runs, fps, out.width, out.height);
  long good = count;  // frames every run could reach (single run: stop at divergence)
  if (runs.size() == 1) good = static_cast<long>(runs[0].frames.size());

  const render::GlBackend backend = plan.backend;
  auto ctx = render::create_gl_context(backend);
  const AaSetting aa = aa_setting(out);
  render::Renderer renderer(*ctx, out.width, out.height, aa.samples(), aa.fxaa());

  for (const Run& r : runs) man.method += (man.method.empty() ? "" : ",") + r.label;
  for (const Run& r : runs) man.step += (man.step.empty() ? "" : ",") + r.step_label;
  man.dt = s.simulation.step.dt;
  man.fps = fps;
  man.width = out.width;
  man.height = out.height;
  man.aa = std::string(scene::antialias_name(out.aa));
  man.msaa = renderer.samples();
  man.frame_count = count;
  man.first = first;
  man.last = last;
  man.gl_version = ctx->version();
  man.gl_renderer = ctx->renderer();
  man.backend = std::string(render::to_string(backend));
  man.frames_out = o.frames_out;
  man.video_format = out.video == scene::VideoFormat::none ? "none" : out.video == scene::VideoFormat::mp4 ? "mp4" : "gif";
  man.crf = plan.quality.crf;

  // From here on, files change: Ctrl-C / SIGTERM stop between frames instead
  // of killing the process, so the manifest tells what is on disk.
  const StopSignals stop;
  if (o.frames_out == "none") {
    io::atomic_write_file(man_path, man.json());
    std::string rerun = "tumble render " + quote_arg(o.scene) + " -o " + quote_arg(dir.string()) + " --frames-out none";
    return stream_render({dir, s, builder, renderer, man, existing, good, o.progress != "none",
                          [&] { return stop.received(); }, rerun, runs[0].diverged.value_or("stopped early")});
  }
  long drawn = 0;  // frames this run submitted (whole on disk once the encoder is flushed)
  auto on_disk = [&] {
    if (man.replacing) return drawn;  // the earlier render's frames are not ours
    long n = 0;
    for (long k = first; k <= last; ++k) n += fs::exists(io::frame_path(dir, k), ec) ? 1 : 0;
    return n;
  };
  if (resume) man.written = on_disk();
  io::atomic_write_file(man_path, man.json());

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
        // Reuse a written frame's buffer: a fresh 3.7 MB buffer per frame costs
        // page faults. The encoder's threads finish it (FXAA) while we draw on.
        render::RawFrame raw = encoder.recycle_raw();
        renderer.render(builder.build(k), raw);
        encoder.submit(io::frame_path(dir, k), std::move(raw));
        ++drawn;
      }
      progress.update(k - first + 1);
    }
    encoder.flush();  // the frames in flight are finished, not dropped
  } catch (const std::runtime_error& e) {  // a frame could not be written: disk full, permissions
    man.written = on_disk();
    try {
      io::atomic_write_file(man_path, man.json());
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
    io::atomic_write_file(man_path, man.json());
    if (signal != 0) {
      std::cerr << "tumble: interrupted (" << (signal == SIGINT ? "SIGINT" : "SIGTERM") << "): kept " << man.written
                << " of " << last - first + 1 << " frames in " << dir.string() << "\n"
                << "tumble: continue with: tumble render " << quote_arg(o.scene) << " -o " << quote_arg(dir.string())
                << (shard ? " --frames " + o.frames : std::string()) << " --resume\n";
      return 128 + signal;
    }
    std::cerr << "tumble: " << runs[0].diverged.value_or("stopped early") << "\n"
              << "tumble: kept " << man.written << " frames in " << dir.string() << "\n";
    return kDiverged;
  }
  // Every new frame exists: the earlier render's other frames can go (before
  // the encode, which would read a stale frame past the last as one of ours).
  // A shard makes no video, so the earlier render's (same name or not) goes too.
  remove_stale(dir, existing, man.settings_hash, own, first, last,
               shard || out.video == scene::VideoFormat::none ? std::string() : video_file_name(s, out.video));
  man.replacing = false;
  const bool full = !shard;  // a shard's video is made by `tumble assemble`
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
      io::atomic_write_file(man_path, man.json());
      std::cerr << "tumble: " << v.message << "\n"
                << "tumble: all " << count << " frames are in " << dir.string() << "; make the video with: tumble render "
                << quote_arg(o.scene) << " -o " << quote_arg(dir.string()) << " --resume\n";
      return v.status == VideoResult::interrupted ? 128 + v.signal : kRuntimeError;
    }
    man.video = video.filename().string();
  }
  io::atomic_write_file(man_path, man.json());
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
  cmd->add_option("--frames-out", o->frames_out,
                  "png (default: frame files, then the video from them) or none (frames piped to ffmpeg as raw "
                  "RGB, only the video is written; an interrupted run keeps nothing)");
  cmd->add_option("--quality", o->quality,
                  "low (no anti-aliasing, CRF 28), medium (the scene's aa, MSAA at most 2x, CRF 23), high (the "
                  "scene's aa, default fxaa; CRF 18)");
  cmd->add_option("--aa", o->aa, "Anti-aliasing fxaa, msaa or none (overrides the scene's aa and --quality)");
  cmd->add_option("--msaa", o->msaa,
                  "MSAA samples 0, 2 or 4 (overrides --quality; alone it also sets aa: msaa, or none for 0)");
  cmd->add_option("--progress", o->progress, "auto (a bar on a terminal) or none");
  cmd->add_option("--gl", o->gl, "osmesa or egl (default: env TUMBLE_GL, else osmesa)");
  cmd->add_flag("--resume", o->resume,
                "Continue an interrupted render in the output folder: frames already on disk are kept");
  cmd->add_flag("--force", o->force,
                "Replace another render (other scene or settings) in the output folder, removing its frames");
  cmd->callback([o, &action] { action = [o] { return run_render(*o); }; });
}

}  // namespace tumble::app
