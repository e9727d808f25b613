// `tumble golden SCENE --at t1,t2 | --frames k1,k2 --dir DIR [--update]`: makes or checks
// golden images (and a golden trajectory) of a scene. Physics is checked
// first, so a physics change is reported as such before the pixels differ.
// Exit 0 all pass (or --update), 1 a golden differs or is missing, 2 bad input.
#include <filesystem>
#include <iostream>
#include <memory>

#include "app/commands.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "golden/compare.hpp"
#include "golden/report.hpp"
#include "golden/trajectory.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"
#include "run/golden_check.hpp"
#include "scene/frame_settings.hpp"

namespace tumble::app {

// Shared with `tumble compare` (cmd_compare.cpp).
void add_golden_tolerance_options(CLI::App* cmd, golden::CompareOptions& c);

namespace {

namespace fs = std::filesystem;

constexpr int kGoldenFailed = 1;

struct GoldenOptions {
  std::string scene, at, frames, dir, report, msaa, aa, gl;
  int width = 320, height = 240;
  long every = 10;
  bool update = false, physics_only = false;
  golden::CompareOptions cmp;
  golden::TrajectoryTolerance tol;
};

int run_golden(const GoldenOptions& o) {
  golden::check_compare_options(o.cmp);
  if (!(o.tol.rtol >= 0) || !(o.tol.atol >= 0)) throw InputError("--rtol/--atol: expected numbers >= 0");
  if (o.every < 1) throw InputError("--every: expected an integer >= 1");
  // GL is set up like an option, before any file is written: an unknown
  // backend or a machine without GL must not leave a half-updated golden set.
  const render::GlBackend backend = o.physics_only ? render::GlBackend::osmesa : parse_backend_option(o.gl);
  try {
    (void)render::gpu_paths_from_env(false);
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
  const std::unique_ptr<render::GlContext> ctx = o.physics_only ? nullptr : render::create_gl_context(backend);
  // The size goes through the scene reader, which checks it as it checks a scene's.
  const scene::Scene s = load_scene_verbose(
      o.scene, {{"--width", "output.width", static_cast<long long>(o.width)},
                {"--height", "output.height", static_cast<long long>(o.height)}});
  const std::vector<scene::FrameSettings> cases = run::golden_cases(o.msaa, o.aa, s.render.output);
  const std::vector<long> ks = run::golden_frames(o.at, o.frames, scene::frame_clock(s, s.render.output.fps));
  const fs::path report_dir = o.report.empty() ? fs::path("golden-report") / s.name : fs::path(o.report);
  std::error_code ec;
  fs::create_directories(o.dir, ec);
  if (ec) throw io::IoError("cannot create " + o.dir + ": " + ec.message());

  // An earlier report is checked (and cleared) before the work.
  golden::Report report(report_dir, "tumble golden: " + s.name + " (" + s.path.string() + ")");
  const run::SceneFrames frames(s, ks.back());
  // A single run that diverged before the last golden frame has no goldens to
  // make or check: exit 3 (as every command), before any golden is written. (In
  // a [compare] scene a method that fails is part of the picture.)
  if (frames.runs().size() == 1)
    if (const scene::Run& r = frames.runs()[0]; r.diverged && static_cast<long>(r.frames.size()) <= ks.back())
      throw Diverged(*r.diverged + "; no golden was written or checked", 0, static_cast<long>(r.frames.size()));
  run::GoldenCheck g{s, frames, ks, o.dir, report, std::cout, o.update, o.every, o.cmp, o.tol};
  g.check_physics();
  if (ctx)
    for (const scene::FrameSettings& f : cases) g.check_images(f, *ctx, backend);
  if (o.update) {
    std::cout << "golden: " << g.written << " file(s) written in " << g.dir.string()
              << " (the rest were already identical); review them and commit\n";
    return kOk;
  }
  if (g.failed) {
    const fs::path index = report.write();
    std::cout << "golden: " << g.failed << " of " << g.cases << " cases FAILED; report: "
              << fs::absolute(index).string() << "\n";
    return kGoldenFailed;
  }
  std::cout << "golden: all " << g.cases << " cases pass\n";
  return kOk;
}

}  // namespace

void add_golden_command(CLI::App& app, Action& action) {
  const auto [cmd, o] = add_command(app, action, "golden",
                                    "Check (or --update) golden images and a golden trajectory of a scene at "
                                    "chosen times", run_golden);
  cmd->add_option("--at", o->at,
                  "Times in s, comma-separated (decimals or fractions such as 1/30); each picks the nearest frame");
  cmd->add_option("--frames", o->frames, "Frame numbers instead of --at, comma-separated (frame k shows t = k/fps)");
  cmd->add_option("--dir", o->dir, "Folder of the goldens (<name>_f<frame>_msaa<N>.png/.json or _fxaa, <name>.trajectory.csv)")
      ->required()
      ->check(kPath);
  cmd->add_flag("--update", o->update, "Write the goldens from this run instead of checking them");
  cmd->add_option("--msaa", o->msaa, "MSAA samples, a list of 0, 2, 4 (default: the scene's aa)");
  cmd->add_option("--aa", o->aa, "Anti-aliasing, a list of fxaa, none, msaa2, msaa4 (default: the scene's)");
  cmd->add_option("--width", o->width, "Image width, px (default 320)");
  cmd->add_option("--height", o->height, "Image height, px (default 240)");
  cmd->add_option("--report", o->report, "Folder of the failure report (default golden-report/<scene name>)")->check(kPath);
  cmd->add_option("--every", o->every, "Golden trajectory: every N-th frame up to the last time (default 10)");
  cmd->add_option("--rtol", o->tol.rtol, "Trajectory relative tolerance (default 1e-6)");
  cmd->add_option("--atol", o->tol.atol, "Trajectory absolute tolerance, SI units (default 1e-9)");
  cmd->add_flag("--physics-only", o->physics_only, "Check only the trajectory (no GL needed)");
  cmd->add_option("--gl", o->gl, "osmesa or egl (default: env TUMBLE_GL, else osmesa)");
  add_golden_tolerance_options(cmd, o->cmp);
}

}  // namespace tumble::app
