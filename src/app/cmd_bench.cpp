// `tumble bench`: the method studies (src/bench); with --scene the
// work-precision study on a user's scene; with --readme-table the README's
// accuracy table; with --render the frame throughput of the demo.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "app/commands.hpp"
#include "core/input_file.hpp"
#include "bench/bench.hpp"
#include "io/atomic_file.hpp"
#ifdef TUMBLE_HAVE_RENDER
#include "run/render_bench.hpp"
#include "render/resource_dir.hpp"
#endif

namespace tumble::app {

namespace {
struct BenchCliOptions {
  bench::BenchOptions studies;
  bool render = false;
  long frames = 240;
  int jobs = 0;  // --render: frame encoder threads; 0 = TUMBLE_JOBS, else the usable cores
  std::string scene, body, readme;
};

constexpr std::size_t kMaxStudiedBodies = 16;  // each body is a full work-precision study

int run_scene_study(const BenchCliOptions& o) {
  const scene::Scene s = load_scene_verbose(o.scene);
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

/// The text of `file`, checked to hold the <!-- BEGIN/END `marker` --> lines
/// (before minutes of measuring).
std::string read_markers(const std::string& file, const std::string& marker) {
  // A regular file only, read without blocking (a FIFO there would hang us);
  // it is rewritten in place, so it is not an input that outputs must avoid.
  constexpr std::size_t kMaxReadmeBytes = std::size_t{16} << 20;
  const std::string text = read_input_file(file, kMaxReadmeBytes, "--readme-table file", ReadRole::own_output);
  try {
    bench::replace_between_markers(text, marker, "");
  } catch (const InputError& e) {
    throw InputError(file + ": " + e.what());
  }
  return text;
}

int rewrite_readme(const std::string& file) {
  const std::string text = read_markers(file, "bench:accuracy-table");
  const std::string table = bench::readme_accuracy_table(std::cout);
  io::atomic_write_file(file, bench::replace_between_markers(text, "bench:accuracy-table", table));
  std::cout << table << "wrote the table into " << file << "\n";
  return kOk;
}

#ifdef TUMBLE_HAVE_RENDER
// --render: one scene's figures, or the demo's and the dense solid's (with
// --readme-table, written into the README's two render blocks).
int run_render_benches(const BenchCliOptions& o) {
  const std::filesystem::path scenes = render::find_resource_dir() / "scenes";
  if (!o.scene.empty() && !o.readme.empty()) throw InputError("--render --readme-table measures the demo; drop --scene");
  if (!o.scene.empty()) {
    run::run_render_bench(o.scene, o.frames, o.studies.out_dir / "render", std::cout, {}, o.jobs);
    return kOk;
  }
  // Anti-aliasing quality also on a comparison grid and on an explained
  // scene (plots, thin curves, much text).
  const std::vector<std::filesystem::path> quality = {scenes / "methods_compare.toml",
                                                      scenes / "dzhanibekov_explained.toml"};
  std::string text;
  if (!o.readme.empty()) {
    read_markers(o.readme, "bench:render-dense");  // both blocks there before minutes of measuring
    text = read_markers(o.readme, "bench:render");
  }
  const run::RenderBenchResult r =
      run::run_render_bench(scenes / "dzhanibekov.toml", o.frames, o.studies.out_dir / "render", std::cout, quality, o.jobs);
  // Then a dense solid (issue #14: a 200k-particle body at >= 10 frames/s).
  const run::RenderBenchResult d =
      run::run_render_bench(scenes / "dense_box.toml", o.frames, o.studies.out_dir / "render_dense", std::cout, {}, o.jobs);
  if (!o.readme.empty()) {
    text = bench::replace_between_markers(text, "bench:render", r.markdown);
    io::atomic_write_file(o.readme, bench::replace_between_markers(text, "bench:render-dense", d.markdown));
    std::cout << "wrote the render figures into " << o.readme << "\n";
  }
  return kOk;
}
#endif

int run_bench(const BenchCliOptions& o) {
  if (!o.readme.empty() && !o.render) {
    if (!o.scene.empty()) throw InputError("--readme-table and --scene: choose one");
    return rewrite_readme(o.readme);
  }
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

}  // namespace

void add_bench_command(CLI::App& app, Action& action) {
  auto o = std::make_shared<BenchCliOptions>();
  CLI::App* cmd = app.add_subcommand("bench", "Work-precision, convergence, stability and drift of every method (+ peers)");
  cmd->add_flag("--quick", o->studies.quick, "Small sweeps and short timing batches (under a minute)");
  cmd->add_option("-o,--out", o->studies.out_dir, "Output folder for CSV, PNG and summary.md")->capture_default_str()->check(kPath);
  auto* render = cmd->add_flag("--render", o->render,
                               "Measure frames/s of the demo render (1280x720, FXAA and 4x MSAA), FXAA's pixels "
                               "against 4x MSAA, and frames/s of a 198k-particle solid instead");
  cmd->add_option("--frames", o->frames, "With --render: how many frames")->capture_default_str();
  cmd->add_option("--jobs", o->jobs,
                  "With --render: frame encoder threads (default: env TUMBLE_JOBS, else the cores this process may use)")
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--scene", o->scene,
                  "Work-precision study (every method x a dt sweep, the adaptive pairs x rtol, the peers that take the body) on this "
                  "scene's bodies against a tight reference; with --render: the scene to render (default "
                  "scenes/dzhanibekov.toml)");
  cmd->add_option("--body", o->body, "With --scene: study only this body")->excludes(render);
  cmd->add_option("--readme-table", o->readme,
                  "Recompute the README's accuracy table and write it between the <!-- BEGIN/END "
                  "bench:accuracy-table --> lines of this file (with --render: the render figures, between "
                  "the bench:render lines)")
      ->check(kPath);
  cmd->callback([o, &action] { action = [o]() -> int { return run_bench(*o); }; });
}

}  // namespace tumble::app
