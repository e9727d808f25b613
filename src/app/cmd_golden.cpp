// `tumble golden SCENE --at t1,t2 | --frames k1,k2 --dir DIR [--update]`: makes or checks
// golden images (and a golden trajectory) of a scene. Physics is checked
// first, so a physics change is reported as such before the pixels differ.
// Exit 0 all pass (or --update), 1 a golden differs or is missing, 2 bad input.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>

#include "app/commands.hpp"
#include "app/frame_renderer.hpp"
#include "core/error.hpp"
#include "golden/compare.hpp"
#include "golden/report.hpp"
#include "golden/trajectory.hpp"
#include "io/atomic_file.hpp"
#include "io/json.hpp"
#include "io/png.hpp"
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

std::string slurp(const fs::path& p, bool& ok) {
  std::ifstream in(p, std::ios::binary);
  ok = static_cast<bool>(in);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A string field of a sidecar, or "?".
std::string sidecar_field(const std::optional<io::Json>& j, const char* key) {
  if (!j) return "?";
  const auto it = j->find(key);
  return it != j->end() && it->is_string() ? it->get<std::string>() : "?";
}

int run_golden(const GoldenOptions& o) {
  check_golden_tolerance(o.cmp);
  if (!(o.tol.rtol >= 0) || !(o.tol.atol >= 0)) throw InputError("--rtol/--atol: expected numbers >= 0");
  if (o.every < 1) throw InputError("--every: expected an integer >= 1");
  for (int v : {o.width, o.height})
    if (v < 16 || v > 16384) throw InputError("--width/--height: expected 16..16384 px, found " + std::to_string(v));
  // GL is set up like an option, before any file is written: an unknown
  // backend or a machine without GL must not leave a half-updated golden set.
  const render::GlBackend backend = o.physics_only ? render::GlBackend::osmesa : parse_backend_option(o.gl);
  const std::unique_ptr<render::GlContext> ctx = o.physics_only ? nullptr : render::create_gl_context(backend);
  const scene::Scene s = load_scene_verbose(o.scene);
  std::vector<AaSetting> aas;
  if (!o.msaa.empty() && !o.aa.empty()) throw InputError("--msaa and --aa: choose one (--aa msaa4 is --msaa 4)");
  if (o.msaa.empty() && o.aa.empty()) aas.push_back(aa_setting(s.render.output));
  for (const std::string& m : split_list(o.msaa)) {
    if (m != "0" && m != "2" && m != "4") throw InputError("--msaa: expected a list of 0, 2, 4, found '" + m + "'");
    aas.push_back(parse_aa_setting("msaa" + m, "--msaa"));
  }
  for (const std::string& a : split_list(o.aa)) aas.push_back(parse_aa_setting(a, "--aa"));
  const double fps = s.render.output.fps;
  const scene::FrameClock clock = scene::frame_clock(s, fps);
  const std::vector<long> ks = golden_frames(o.at, o.frames, clock);
  const fs::path dir = o.dir;
  const fs::path report_dir = o.report.empty() ? fs::path("golden-report") / s.name : fs::path(o.report);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw io::IoError("cannot create " + dir.string() + ": " + ec.message());

  const SceneFrames frames(s, ks.back());
  golden::Report report(report_dir, "tumble golden: " + s.name + " (" + s.path.string() + ")");
  int failed = 0, cases = 0, written = 0;
  auto line = [&](bool pass, const std::string& status, const std::string& what, const std::string& figures) {
    ++cases;
    failed += !pass;
    std::cout << status << "  " << what << ": " << figures << "\n";
  };

  // Golden physics: every `every`-th frame up to the last golden time, plus the golden frames.
  {
    std::set<long> rows(ks.begin(), ks.end());
    for (long k = 0; k <= ks.back(); k += o.every) rows.insert(k);
    const std::string actual = frames.trajectory_csv({rows.begin(), rows.end()});
    const fs::path path = dir / (s.name + ".trajectory.csv");
    bool ok = false;
    const std::string expected = slurp(path, ok);
    const std::string what = "physics " + path.filename().string();
    if (o.update) {
      if (!ok || expected != actual) {
        io::atomic_write_file(path, actual);
        ++written;
        std::cout << (ok ? "updated  " : "created  ") << path.string()
                  << (ok ? "  (was: " + golden::compare_trajectories(actual, expected, o.tol).summary + ")" : "") << "\n";
      }
    } else if (!ok) {
      const std::string msg = "no golden " + path.string() + "; run with --update (or TUMBLE_UPDATE_GOLDENS=1 ctest -L golden) to create it";
      line(false, "MISSING", what, msg);
      report.add_text(what, false, "MISSING", msg);
    } else {
      const golden::TrajectoryComparison c = golden::compare_trajectories(actual, expected, o.tol);
      line(c.pass, c.pass ? "PASS   " : "PHYSICS", what, c.summary);
      report.add_text(what, c.pass, c.pass ? "pass" : "PHYSICS CHANGED", c.summary);
    }
  }

  if (ctx) {
    const std::string gl_renderer = ctx->renderer(), gl_version = ctx->version();
    for (const AaSetting& aa : aas) {
      int samples = 0;
      const std::vector<io::Image> images = frames.render(*ctx, ks, o.width, o.height, aa, &samples);
      for (std::size_t i = 0; i < ks.size(); ++i) {
        const long k = ks[i];
        char base[160];
        std::snprintf(base, sizeof base, "%s_f%06ld_%s", s.name.c_str(), k, aa.name().c_str());
        const fs::path png = dir / (std::string(base) + ".png"), side = dir / (std::string(base) + ".json");
        char what[200];
        std::snprintf(what, sizeof what, "%s t=%.6g s (frame %ld) %s %dx%d", s.name.c_str(), clock.time(k), k,
                      aa.name().c_str(), o.width, o.height);
        const io::Image& actual = images[i];
        std::optional<io::Image> expected;
        std::string read_error;
        if (fs::exists(png)) {
          try {
            expected = io::read_png(png);
          } catch (const std::exception& e) {
            read_error = e.what();
          }
        }
        if (o.update) {
          io::Json j{{"scene", s.path.filename().string()}, {"t", clock.time(k)},
                           {"frame", k}, {"fps", fps}, {"width", o.width}, {"height", o.height}, {"msaa", aa.samples()},
                           {"samples", samples}, {"gl_backend", render::to_string(backend)},
                           {"gl_renderer", gl_renderer}, {"gl_version", gl_version},
                           {"tumble_version", TUMBLE_VERSION}};
          if (aa.fxaa()) j["aa"] = "fxaa";  // msaa goldens keep their sidecars as they were
          const bool same = expected && expected->width == actual.width && expected->height == actual.height &&
                            expected->rgb == actual.rgb;
          const std::optional<io::Json> old_side = io::read_json_file(side);
          const bool side_same = old_side && *old_side == j;  // by value: 30 and 30.0 are one fps
          if (!same) {
            io::write_png_atomic(png, actual);
            std::cout << (expected ? "updated  " : "created  ") << png.string()
                      << (expected ? "  (was: " + golden::compare_images(actual, *expected, o.cmp).summary + ")" : "")
                      << "\n";
          }
          if (!same || !side_same) {
            io::write_json_atomic(side, j);
            ++written;
          }
          continue;
        }
        const std::optional<io::Json> sidecar = io::read_json_file(side);
        const std::string note = "expected made with " +
                                 (sidecar ? sidecar_field(sidecar, "gl_renderer") + ", " + sidecar_field(sidecar, "gl_version")
                                          : std::string("? (no sidecar ") + side.filename().string() + ")") +
                                 "; actual with " + gl_renderer + ", " + gl_version;
        if (!fs::exists(png)) {
          const std::string msg = "no golden " + png.string() + "; run with --update (or TUMBLE_UPDATE_GOLDENS=1 ctest -L golden) to create it";
          line(false, "MISSING", what, msg);
          report.add_image(base, what, actual, nullptr, nullptr, o.cmp, false, "MISSING", msg);
          continue;
        }
        if (!expected) {
          line(false, "UNREADABLE", what, read_error);
          report.add_image(base, what, actual, nullptr, nullptr, o.cmp, false, "UNREADABLE", read_error);
          continue;
        }
        const golden::Comparison c = golden::compare_images(actual, *expected, o.cmp);
        line(c.pass, c.pass ? "PASS   " : "FAIL   ", what, c.summary);
        report.add_image(base, what, actual, &*expected, &c, o.cmp, c.pass, c.pass ? "pass" : "FAIL", note);
      }
    }
  }
  if (o.update) {
    std::cout << "golden: " << written << " file(s) written in " << dir.string()
              << " (the rest were already identical); review them and commit\n";
    return kOk;
  }
  if (failed) {
    const fs::path index = report.write();
    std::cout << "golden: " << failed << " of " << cases << " cases FAILED; report: " << fs::absolute(index).string()
              << "\n";
    return kGoldenFailed;
  }
  std::cout << "golden: all " << cases << " cases pass\n";
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
