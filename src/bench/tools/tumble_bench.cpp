// tumble-bench (`tumble bench` runs it): the method studies (src/bench); with
// --scene the work-precision study on a user's scene; with --render the frame
// throughput of a scene, or of the demo and a dense solid.
#include <CLI/CLI.hpp>

#include <csignal>
#include <filesystem>
#include <iostream>
#include <memory>

#include "app/commands.hpp"
#include "bench/bench.hpp"
#ifdef TUMBLE_HAVE_RENDER
#include "bench/render/render_bench.hpp"
#include "render/resource_dir.hpp"
#endif

namespace {

using namespace tumble;

struct BenchCliOptions {
  bench::BenchOptions studies;
  bool render = false;
  long frames = 240;
  int jobs = 0;  // --render: frame encoder threads; 0 = TUMBLE_JOBS, else the usable cores
  std::string scene, body;
};

constexpr std::size_t kMaxStudiedBodies = 16;  // each body is a full work-precision study

int run_scene_study(const BenchCliOptions& o) {
  const scene::Scene s = app::load_scene_verbose(o.scene);
  std::vector<bench::Problem> problems;
  for (const scene::Body& b : s.bodies)
    if (o.body.empty() || b.name == o.body)
      problems.push_back(bench::body_problem(b.name, b.model, b.initial, s.simulation.duration));
  if (problems.empty()) {
    std::string names;
    for (const scene::Body& b : s.bodies) names += (names.empty() ? "" : ", ") + b.name;
    throw InputError("--body: no body \"" + o.body + "\" in " + o.scene + " (bodies: " + names + ")");
  }
  if (problems.size() > kMaxStudiedBodies)
    throw InputError(o.scene + " has " + std::to_string(problems.size()) + " bodies; bench --scene studies at most " +
                     std::to_string(kMaxStudiedBodies) + ": choose one with --body NAME");
  return bench::run_problems(o.studies, s.name, problems, std::cout);
}

#ifdef TUMBLE_HAVE_RENDER
// --render: one scene's figures, or the demo's (with anti-aliasing quality on
// a comparison grid and an explained scene: plots, thin curves, much text)
// and a dense solid's (a 200k-particle body, meant to draw at >= 10 frames/s).
int run_render_benches(const BenchCliOptions& o) {
  if (!o.scene.empty()) {
    bench::run_render_bench(o.scene, o.frames, o.studies.out_dir / "render", std::cout, {}, o.jobs);
    return app::kOk;
  }
  const std::filesystem::path scenes = render::find_resource_dir() / "scenes";
  bench::run_render_bench(scenes / "dzhanibekov.toml", o.frames, o.studies.out_dir / "render", std::cout,
                          {scenes / "methods_compare.toml", scenes / "dzhanibekov_explained.toml"}, o.jobs);
  bench::run_render_bench(scenes / "dense_box.toml", o.frames, o.studies.out_dir / "render_dense", std::cout, {},
                          o.jobs);
  return app::kOk;
}
#endif

int run_bench(const BenchCliOptions& o) {
  io::check_output_folder("bench -o", o.studies.out_dir);
  if (!o.render) {
    if (!o.body.empty() && o.scene.empty()) throw InputError("--body needs --scene");
    return o.scene.empty() ? bench::run(o.studies, std::cout) : run_scene_study(o);
  }
#ifdef TUMBLE_HAVE_RENDER
  return run_render_benches(o);
#else
  throw InputError("this build has no renderer (TUMBLE_BUILD_RENDER=OFF)");
#endif
}

void add_options(CLI::App& cmd, BenchCliOptions& o) {
  cmd.add_flag("--quick", o.studies.quick, "Small sweeps and short timing batches (under a minute)");
  cmd.add_option("-o,--out", o.studies.out_dir, "Output folder for CSV, PNG and summary.md")->capture_default_str()->check(app::kPath);
  auto* render = cmd.add_flag("--render", o.render,
                              "Measure frames/s of the demo render (1280x720, FXAA and 4x MSAA), FXAA's pixels "
                              "against 4x MSAA, and frames/s of a 198k-particle solid instead");
  cmd.add_option("--frames", o.frames, "With --render: how many frames")->capture_default_str();
  cmd.add_option("--jobs", o.jobs,
                 "With --render: frame encoder threads (default: env TUMBLE_JOBS, else the cores this process may use)")
      ->check(CLI::Range(1, 1024));
  cmd.add_option("--scene", o.scene,
                 "Work-precision study (every method x a dt sweep, the adaptive pairs x rtol, the peers that take the body) on this "
                 "scene's bodies against a tight reference; with --render: the scene to render (default "
                 "scenes/dzhanibekov.toml)");
  cmd.add_option("--body", o.body, "With --scene: study only this body")->excludes(render);
}

}  // namespace

int main(int argc, char** argv) {
  std::signal(SIGXFSZ, SIG_IGN);  // past ulimit -f a write fails with EFBIG, reported, instead of killing us
  CLI::App cmd{"Work-precision, convergence, stability and drift of every method (+ peers)", "tumble bench"};
  auto o = std::make_shared<BenchCliOptions>();
  add_options(cmd, *o);
  try {
    cmd.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = cmd.exit(e);
    return rc == 0 ? 0 : app::kInputError;  // usage errors are input errors
  }
  return app::run_action([o] { return run_bench(*o); });
}
