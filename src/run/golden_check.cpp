#include "run/golden_check.hpp"

#include <cmath>
#include <cstdio>
#include <optional>
#include <set>
#include <sstream>

#include "base/error.hpp"
#include "base/input_file.hpp"
#include "io/atomic_file.hpp"
#include "io/json.hpp"
#include "io/png.hpp"
#include "base/format.hpp"

namespace tumble::run {

namespace {

namespace fs = std::filesystem;

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

constexpr std::size_t kMaxTrajectoryBytes = std::size_t(256) << 20;

/// A golden file's bytes ("" and !ok when missing). A golden is this run's
/// input, unless --update may rewrite it.
std::string slurp(const fs::path& p, bool& ok, bool update) {
  const std::optional<std::string> text = read_file_if_exists(
      p, kMaxTrajectoryBytes, "golden trajectory", update ? ReadRole::own_output : ReadRole::input);
  ok = text.has_value();
  return text.value_or("");
}

/// A string field of a sidecar, or "?".
std::string sidecar_field(const std::optional<io::Json>& j, const char* key) {
  if (!j) return "?";
  const auto it = j->find(key);
  return it != j->end() && it->is_string() ? it->get<std::string>() : "?";
}

}  // namespace

// Frame k = round(video_time(t) * fps) for a time t.
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

std::vector<scene::FrameSettings> golden_cases(const std::string& msaa, const std::string& aa,
                                               const scene::FrameSettings& scene_frame) {
  if (!msaa.empty() && !aa.empty()) throw InputError("--msaa and --aa: choose one (--aa msaa4 is --msaa 4)");
  std::vector<scene::FrameSettings> cases;
  if (msaa.empty() && aa.empty()) cases.push_back(scene_frame);
  auto add = [&](const std::string& name, const std::string& what) {
    scene::FrameSettings f = scene_frame;
    if (!scene::parse_aa_case(name, f)) throw InputError(what);
    cases.push_back(f);
  };
  for (const std::string& m : split_list(msaa))
    add("msaa" + m, "--msaa: expected a list of 0, 2, 4, found '" + m + "'");
  for (const std::string& a : split_list(aa))
    add(a, "--aa: expected " + scene::aa_case_choices() + ", found '" + a + "'");
  return cases;
}

void GoldenCheck::check_physics() {
  GoldenCheck& g = *this;
  std::set<long> rows(g.ks.begin(), g.ks.end());
  for (long k = 0; k <= g.ks.back(); k += g.every) rows.insert(k);
  const std::string actual = g.frames.trajectory_csv({rows.begin(), rows.end()});
  const fs::path path = g.dir / (g.s.name + ".trajectory.csv");
  bool ok = false;
  const std::string expected = slurp(path, ok, g.update);
  const std::string what = "physics " + path.filename().string();
  if (g.update) {
    if (!ok || expected != actual) {
      io::atomic_write_file(path, actual);
      ++g.written;
      g.out << (ok ? "updated  " : "created  ") << path.string()
                << (ok ? "  (was: " + golden::compare_trajectories(actual, expected, g.tol).summary + ")" : "") << "\n";
    }
  } else if (!ok) {
    g.line(false, "MISSING", what, g.missing(path));
    g.report.add_text(what, false, "MISSING", g.missing(path));
  } else {
    const golden::TrajectoryComparison c = golden::compare_trajectories(actual, expected, g.tol);
    g.line(c.pass, c.pass ? "PASS   " : "PHYSICS", what, c.summary);
    g.report.add_text(what, c.pass, c.pass ? "pass" : "PHYSICS CHANGED", c.summary);
  }
}

namespace {

/// One golden image and its sidecar, as this run would write them.
struct GoldenImage {
  std::string base, what;
  fs::path png, side;
  const io::Image& actual;
  std::optional<io::Image> expected;
  std::string read_error;
};

/// --update: writes the image and the sidecar `j` where they differ from the files.
void update_image(GoldenCheck& g, const GoldenImage& im, const io::Json& j) {
  const std::optional<io::Image>& expected = im.expected;
  const bool same = expected && expected->width == im.actual.width && expected->height == im.actual.height &&
                    expected->rgb == im.actual.rgb;
  const std::optional<io::Json> old_side = io::read_json_file(im.side);
  const bool side_same = old_side && *old_side == j;  // by value: 30 and 30.0 are one fps
  if (!same) {
    io::write_png_atomic(im.png, im.actual);
    g.out << (expected ? "updated  " : "created  ") << im.png.string()
              << (expected ? "  (was: " + golden::compare_images(im.actual, *expected, g.cmp).summary + ")" : "")
              << "\n";
  }
  if (!same || !side_same) {
    io::write_json_atomic(im.side, j);
    ++g.written;
  }
}

void check_image(GoldenCheck& g, const GoldenImage& im, const render::GlContext& ctx) {
  const std::optional<io::Json> sidecar = io::read_json_file(im.side);
  const std::string note = "expected made with " +
                           (sidecar ? sidecar_field(sidecar, "gl_renderer") + ", " + sidecar_field(sidecar, "gl_version")
                                    : std::string("? (no sidecar ") + im.side.filename().string() + ")") +
                           "; actual with " + ctx.renderer() + ", " + ctx.version();
  if (!fs::exists(im.png)) {
    g.line(false, "MISSING", im.what, g.missing(im.png));
    g.report.add_image(im.base, im.what, im.actual, nullptr, nullptr, g.cmp, false, "MISSING", g.missing(im.png));
  } else if (!im.expected) {
    g.line(false, "UNREADABLE", im.what, im.read_error);
    g.report.add_image(im.base, im.what, im.actual, nullptr, nullptr, g.cmp, false, "UNREADABLE", im.read_error);
  } else {
    const golden::Comparison c = golden::compare_images(im.actual, *im.expected, g.cmp);
    g.line(c.pass, c.pass ? "PASS   " : "FAIL   ", im.what, c.summary);
    g.report.add_image(im.base, im.what, im.actual, &*im.expected, &c, g.cmp, c.pass, c.pass ? "pass" : "FAIL", note);
  }
}

}  // namespace

/// Every golden frame in anti-aliasing case `f`: checked, or written with --update.
void GoldenCheck::check_images(const scene::FrameSettings& f, render::GlContext& ctx, render::GlBackend backend) {
  GoldenCheck& g = *this;
  const scene::FrameClock clock = scene::frame_clock(g.s, g.s.render.output.fps);
  int samples = 0;
  const std::vector<io::Image> images = g.frames.render(ctx, g.ks, f, &samples);
  const std::string aa = f.aa_case();
  for (std::size_t i = 0; i < g.ks.size(); ++i) {
    const long k = g.ks[i];
    char base[160];
    std::snprintf(base, sizeof base, "%s_f%06ld_%s", g.s.name.c_str(), k, aa.c_str());
    char what[200];
    std::snprintf(what, sizeof what, "%s t=%.6g s (frame %ld) %s %dx%d", g.s.name.c_str(), clock.time(k), k,
                  aa.c_str(), f.width, f.height);
    GoldenImage im{base, what, g.dir / (std::string(base) + ".png"), g.dir / (std::string(base) + ".json"),
                   images[i], std::nullopt, {}};
    if (fs::exists(im.png)) {
      try {
        im.expected = io::read_png(im.png, g.update ? ReadRole::own_output : ReadRole::input);
      } catch (const std::exception& e) {
        im.read_error = e.what();
      }
    }
    if (!g.update) {
      check_image(g, im, ctx);
      continue;
    }
    io::Json j{{"scene", g.s.path.filename().string()}, {"t", clock.time(k)}, {"frame", k},
               {"fps", g.s.render.output.fps}, {"width", f.width}, {"height", f.height}, {"msaa", f.samples()},
               {"samples", samples}, {"gl_backend", render::to_string(backend)}, {"gl_renderer", ctx.renderer()},
               {"gl_version", ctx.version()}, {"tumble_version", TUMBLE_VERSION}};
    if (f.fxaa()) j["aa"] = std::string(scene::antialias_name(f.aa));  // msaa goldens keep their sidecars as they were
    update_image(g, im, j);
  }
}

void GoldenCheck::line(bool pass, const std::string& status, const std::string& what, const std::string& figures) {
  ++cases;
  failed += !pass;
  out << status << "  " << what << ": " << figures << "\n";
}

std::string GoldenCheck::missing(const fs::path& path) const {
  return "no golden " + path.string() + "; run with --update (or TUMBLE_UPDATE_GOLDENS=1 ctest -L golden) to create it";
}

}  // namespace tumble::run
