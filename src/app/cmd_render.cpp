// `tumble render SCENE`: frames (PNG, atomic), manifest.json and a video.
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>

#include "app/commands.hpp"
#include "app/progress.hpp"
#include "io/atomic_file.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"
#include "render/worker_threads.hpp"
#include "run/layout_run.hpp"
#include "run/render_folder.hpp"
#include "scene/scene.hpp"

namespace tumble::app {

namespace {

namespace fs = std::filesystem;

struct RenderOptions {
  std::string scene, out_dir, frames, video, quality = "high", progress = "auto", gl, frames_out = "png", layout;
  FrameOverrides frame;
  std::optional<int> gpu;
  int jobs = 0;  // 0: TUMBLE_JOBS, else the cores this process may use
  bool resume = false, force = false;
};

}  // namespace

std::vector<scene::Override> frame_overrides(const FrameOverrides& o) {
  std::vector<scene::Override> v;
  if (o.width) v.push_back({"--width", "output.width", static_cast<long long>(*o.width)});
  if (o.height) v.push_back({"--height", "output.height", static_cast<long long>(*o.height)});
  if (o.fps) v.push_back({"--fps", "output.fps", *o.fps});
  if (o.msaa) v.push_back({"--msaa", "output.msaa", static_cast<long long>(*o.msaa)});
  // --msaa N alone means what it always did: N samples, 0 none.
  if (o.msaa && o.aa.empty()) v.push_back({"--msaa", "output.aa", std::string(*o.msaa > 0 ? "msaa" : "none")});
  if (!o.aa.empty()) v.push_back({"--aa", "output.aa", o.aa});
  return v;
}

void add_frame_override_options(CLI::App* cmd, FrameOverrides& o, bool quality) {
  cmd->add_option("--width", o.width, "Frame width, px");
  cmd->add_option("--height", o.height, "Frame height, px");
  cmd->add_option("--fps", o.fps, "Frames per second (frame k shows t = k·time_scale/fps)");
  const std::string over = quality ? " and --quality" : "";
  cmd->add_option("--aa", o.aa, "Anti-aliasing fxaa, msaa or none (overrides the scene's aa" + over + ")");
  cmd->add_option("--msaa", o.msaa,
                  "MSAA samples 0, 2 or 4 (overrides the scene's msaa" + over +
                      "; alone it also sets aa: msaa, or none for 0)");
}

render::GlBackend parse_backend_option(const std::string& gl) {
  const std::string where = gl.empty() ? "TUMBLE_GL" : "--gl";
  try {
    return gl.empty() ? render::default_gl_backend() : render::parse_gl_backend(gl);
  } catch (const std::invalid_argument& e) {
    throw InputError(where + ": " + e.what());
  }
}

GlChoice choose_gl(const std::string& gl, std::optional<int> gpu) {
  // --gpu N means an EGL device: a user picking a GPU wants it drawing.
  if (gpu && gl == "osmesa") throw InputError("--gpu chooses an EGL device; it needs --gl egl, not osmesa");
  GlChoice c{gpu ? render::GlBackend::egl : parse_backend_option(gl), gpu};
  try {  // the environment's device is checked before any work, as the options are
    if (!c.gpu && c.backend == render::GlBackend::egl) c.gpu = render::default_egl_device();
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
  return c;
}

void add_gl_options(CLI::App* cmd, std::string& gl, std::optional<int>& gpu) {
  cmd->add_option("--gl", gl, "osmesa or egl (default: env TUMBLE_GL, else osmesa)");
  cmd->add_option("--gpu", gpu,
                  "EGL device N of eglQueryDevicesEXT (implies --gl egl; default: env TUMBLE_EGL_DEVICE, else "
                  "Mesa's surfaceless display or device 0)")
      ->check(CLI::Range(0, 1023));
}

namespace {

/// The options that are scene keys go into the scene before it is validated,
/// so the loader's checks (sizes, frame cap, names) cover them too.
std::vector<scene::Override> scene_overrides(const RenderOptions& o) {
  std::vector<scene::Override> v = frame_overrides(o.frame);
  if (!o.video.empty()) v.push_back({"--video", "output.video", o.video});
  return v;
}

/// The scene with the options applied, every option checked before any work.
struct RenderPlan {
  scene::Scene scene;
  render::GlBackend backend;
  std::optional<int> gpu;  // EGL device: --gpu, else TUMBLE_EGL_DEVICE
  int jobs;                // frame encoder threads
};

RenderPlan plan_render(const RenderOptions& o) {
  const std::optional<scene::Quality> q = scene::parse_quality(o.quality);
  if (!q) throw InputError("--quality: expected " + scene::quality_choices() + ", found '" + o.quality + "'");
  if (o.progress != "auto" && o.progress != "none")
    throw InputError("--progress: expected auto or none, found '" + o.progress + "'");
  if (o.frames_out != "png" && o.frames_out != "none")
    throw InputError("--frames-out: expected png or none, found '" + o.frames_out + "'");
  const GlChoice gl = choose_gl(o.gl, o.gpu);
  int jobs = 0;
  try {  // the environment's values are checked before any work, as the options are
    jobs = render::worker_threads(o.jobs);
    (void)render::gpu_paths_from_env(false);  // TUMBLE_GPU_PATHS, read again once the GL context is known
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
  scene::Scene s = load_scene_verbose(o.scene, scene_overrides(o));
  scene::OutputConfig& out = s.render.output;
  if (o.frames_out == "none" && out.video == scene::VideoFormat::none)
    throw InputError("--frames-out none writes only the video, and the video is none: nothing to write; "
                     "choose --video mp4 or gif");
  if (o.frames_out == "none" && !o.frames.empty())
    throw InputError("--frames-out none streams the whole video; --frames needs PNG frames (--frames-out png)");
  out.apply_quality(*q, o.frame.msaa || !o.frame.aa.empty());
  return {std::move(s), gl.backend, gl.gpu, jobs};
}

// --layout FILE: the layout report of the asked frames, no pixels (no GL, no output folder).
int run_layout(const RenderOptions& o) {
  const scene::Scene s = load_scene_verbose(o.scene, scene_overrides(o));
  io::check_output_file("--layout", o.layout);  // after the load: no spelling of the scene (or its meshes) passes
  const run::LayoutSummary r = run::write_layout_report(s, o.frames, o.layout);
  for (const std::string& note : r.notes) std::cerr << "tumble: warning: " << note << "\n";
  std::cout << "wrote the layout of frames " << r.first << ".." << r.last << " of " << r.count << " (" << r.width
            << "x" << r.height << ") to " << o.layout << "\n";
  return kOk;
}

int run_render(const RenderOptions& o) {
  if (!o.layout.empty()) return run_layout(o);
  const RenderPlan plan = plan_render(o);
  const fs::path dir = o.out_dir.empty() ? fs::path("out") / plan.scene.name : fs::path(o.out_dir);
  const run::RenderRequest req{plan.scene, dir,     o.frames, o.resume, o.force, o.frames_out == "none",
                               plan.backend, o.scene, plan.gpu, plan.jobs};
  ConsoleListener listener(o.progress != "none");
  return exit_code(run::render_scene(req, listener));
}

}  // namespace

void add_render_command(CLI::App& app, Action& action) {
  const auto [cmd, o] = add_command(app, action, "render",
                                    "Render a scene headless to PNG frames, a manifest and a video", run_render);
  cmd->add_option("-o,--out", o->out_dir, "Output folder (default out/<scene name>)")->check(kPath);
  add_frame_override_options(cmd, o->frame, true);
  cmd->add_option("--frames", o->frames, "Render only frames A:B (inclusive); pixels equal a full run's");
  cmd->add_option("--video", o->video, scene::video_format_choices() + " (default: the scene's [output] video)");
  cmd->add_option("--frames-out", o->frames_out,
                  "png (default: frame files, then the video from them) or none (frames piped to ffmpeg as raw "
                  "RGB, only the video is written; an interrupted run keeps nothing)");
  cmd->add_option("--quality", o->quality,
                  "low (no anti-aliasing, CRF 28), medium (the scene's aa, MSAA at most 2x, CRF 23), high (the "
                  "scene's aa, default fxaa; CRF 18)");
  cmd->add_option("--progress", o->progress, "auto (a bar on a terminal) or none");
  cmd->add_option("--layout", o->layout,
                  "Write only the layout report, JSON Lines (frame, view, name, kind, box, visible per drawn item), "
                  "to this file: no pixels, no output folder")
      ->check(kPath);
  add_gl_options(cmd, o->gl, o->gpu);
  cmd->add_option("--jobs", o->jobs,
                  "Frame encoder threads (default: env TUMBLE_JOBS, else the cores this process may use: "
                  "affinity mask and cgroup CPU quota); the frames' bytes do not depend on it")
      ->check(CLI::Range(1, 1024));
  cmd->add_flag("--resume", o->resume,
                "Continue an interrupted render in the output folder: frames already on disk are kept");
  cmd->add_flag("--force", o->force,
                "Replace another render (other scene or settings) in the output folder, removing its frames");
}

}  // namespace tumble::app
