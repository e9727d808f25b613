// `tumble golden SCENE --at t1,t2 | --frames k1,k2 --dir DIR [--update]`: makes or checks
// golden images (and a golden trajectory) of a scene. Physics is checked
// first, so a physics change is reported as such before the pixels differ.
// Exit 0 all pass (or --update), 1 a golden differs or is missing, 2 bad input.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>

#include "app/commands.hpp"
#include "run/golden_check.hpp"
#include "scene/frame_settings.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "golden/compare.hpp"
#include "golden/report.hpp"
#include "golden/trajectory.hpp"
#include "render/gl_context.hpp"

namespace tumble::app {

// Shared with `tumble compare` (cmd_compare.cpp).
void add_golden_tolerance_options(CLI::App* cmd, golden::CompareOptions& c);
void check_golden_tolerance(const golden::CompareOptions& c);

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

std::vector<std::string> split_list(const std::string& s) {
  std::vector<std::string> out;
  std::istringstream in(s);
  for (std::string f; std::getline(in, f, ',');)
    if (!f.empty()) out.push_back(f);
  return out;
}

double parse_num(const std::string& what, const std::string& s) {
  std::size_t used = 0;
  double v = NAN;
  try {
    v = std::stod(s, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != s.size() || !std::isfinite(v)) throw InputError(what + ": expected a number, found '" + s + "'");
  return v;
}

/// A time in s: a decimal number or a simple fraction "a/b" (e.g. 1/30).
double parse_time(const std::string& s) {
  const auto slash = s.find('/');
  if (slash == std::string::npos) return parse_num("--at", s);
  const double den = parse_num("--at", s.substr(slash + 1));
  if (den == 0) throw InputError("--at " + s + ": division by zero");
  return parse_num("--at", s.substr(0, slash)) / den;
}

/// Golden frames from `--at` times (each matched to the nearest frame k =
/// round(video_time(t) * fps), so any time within half a frame of a frame
/// time names that frame; time_scale / slow motion are the clock's) or from `--frames` numbers; sorted, without repeats.
std::vector<long> golden_frames(const std::string& at, const std::string& frames, const scene::FrameClock& clock) {
  const double fps = clock.fps();
  const long count = clock.count();
  if (at.empty() == frames.empty())
    throw InputError(at.empty() ? "give --at times or --frames numbers, e.g. --at 0.5,2 or --frames 15,60"
                                : "--at and --frames: give one of them, not both");
  const bool by_time = !at.empty();
  const char* opt = by_time ? "--at" : "--frames";
  const auto items = split_list(by_time ? at : frames);
  if (items.empty()) throw InputError(std::string(opt) + ": expected a comma-separated list, e.g. " +
                                      (by_time ? "--at 0.5,2" : "--frames 15,60"));
  std::set<long> ks;
  for (const std::string& item : items) {
    double k = 0;
    if (by_time) {
      const double t = parse_time(item);
      if (t < 0) throw InputError("--at " + item + ": expected a time >= 0 s");
      k = std::round(clock.video_time(t) * fps);
    } else {
      k = parse_num("--frames", item);
      if (k < 0 || k != std::floor(k)) throw InputError("--frames " + item + ": expected a frame number (integer >= 0)");
    }
    if (k >= static_cast<double>(count))
      throw InputError(std::string(opt) + " " + item + ": past the end of the scene (last frame " +
                       std::to_string(count - 1) + ", t = " + format_number(clock.time(count - 1)) + " s)");
    ks.insert(static_cast<long>(k));
  }
  return {ks.begin(), ks.end()};
}

/// The anti-aliasing cases to check, each at the command's size: --msaa's
/// or --aa's list, else the scene's own.
std::vector<scene::FrameSettings> golden_cases(const GoldenOptions& o, const scene::Scene& s) {
  if (!o.msaa.empty() && !o.aa.empty()) throw InputError("--msaa and --aa: choose one (--aa msaa4 is --msaa 4)");
  std::vector<scene::FrameSettings> cases;
  if (o.msaa.empty() && o.aa.empty()) cases.push_back(s.render.output);
  auto add = [&](const std::string& name, const std::string& what) {
    scene::FrameSettings f = s.render.output;
    if (!scene::parse_aa_case(name, f)) throw InputError(what);
    cases.push_back(f);
  };
  for (const std::string& m : split_list(o.msaa))
    add("msaa" + m, "--msaa: expected a list of 0, 2, 4, found '" + m + "'");
  for (const std::string& a : split_list(o.aa))
    add(a, "--aa: expected " + scene::aa_case_choices() + ", found '" + a + "'");
  return cases;
}

int run_golden(const GoldenOptions& o) {
  check_golden_tolerance(o.cmp);
  if (!(o.tol.rtol >= 0) || !(o.tol.atol >= 0)) throw InputError("--rtol/--atol: expected numbers >= 0");
  if (o.every < 1) throw InputError("--every: expected an integer >= 1");
  // GL is set up like an option, before any file is written: an unknown
  // backend or a machine without GL must not leave a half-updated golden set.
  const render::GlBackend backend = o.physics_only ? render::GlBackend::osmesa : parse_backend_option(o.gl);
  const std::unique_ptr<render::GlContext> ctx = o.physics_only ? nullptr : render::create_gl_context(backend);
  // The size goes through the scene reader, which checks it as it checks a scene's.
  const scene::Scene s = load_scene_verbose(
      o.scene, {{"--width", "output.width", static_cast<long long>(o.width)},
                {"--height", "output.height", static_cast<long long>(o.height)}});
  const std::vector<scene::FrameSettings> cases = golden_cases(o, s);
  const std::vector<long> ks = golden_frames(o.at, o.frames, scene::frame_clock(s, s.render.output.fps));
  const fs::path report_dir = o.report.empty() ? fs::path("golden-report") / s.name : fs::path(o.report);
  std::error_code ec;
  fs::create_directories(o.dir, ec);
  if (ec) throw io::IoError("cannot create " + o.dir + ": " + ec.message());

  const run::SceneFrames frames(s, ks.back());
  golden::Report report(report_dir, "tumble golden: " + s.name + " (" + s.path.string() + ")");
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
  auto o = std::make_shared<GoldenOptions>();
  CLI::App* cmd = app.add_subcommand(
      "golden", "Check (or --update) golden images and a golden trajectory of a scene at chosen times");
  cmd->add_option("scene", o->scene, "Scene file (TOML)")->required();
  cmd->add_option("--at", o->at,
                  "Times in s, comma-separated (decimals or fractions such as 1/30); each picks the nearest frame");
  cmd->add_option("--frames", o->frames, "Frame numbers instead of --at, comma-separated (frame k shows t = k/fps)");
  cmd->add_option("--dir", o->dir, "Folder of the goldens (<name>_f<frame>_msaa<N>.png/.json or _fxaa, <name>.trajectory.csv)")
      ->required();
  cmd->add_flag("--update", o->update, "Write the goldens from this run instead of checking them");
  cmd->add_option("--msaa", o->msaa, "MSAA samples, a list of 0, 2, 4 (default: the scene's aa)");
  cmd->add_option("--aa", o->aa, "Anti-aliasing, a list of fxaa, none, msaa2, msaa4 (default: the scene's)");
  cmd->add_option("--width", o->width, "Image width, px (default 320)");
  cmd->add_option("--height", o->height, "Image height, px (default 240)");
  cmd->add_option("--report", o->report, "Folder of the failure report (default golden-report/<scene name>)");
  cmd->add_option("--every", o->every, "Golden trajectory: every N-th frame up to the last time (default 10)");
  cmd->add_option("--rtol", o->tol.rtol, "Trajectory relative tolerance (default 1e-6)");
  cmd->add_option("--atol", o->tol.atol, "Trajectory absolute tolerance, SI units (default 1e-9)");
  cmd->add_flag("--physics-only", o->physics_only, "Check only the trajectory (no GL needed)");
  cmd->add_option("--gl", o->gl, "osmesa or egl (default: env TUMBLE_GL, else osmesa)");
  add_golden_tolerance_options(cmd, o->cmp);
  cmd->callback([o, &action] { action = [o] { return run_golden(*o); }; });
}

}  // namespace tumble::app
