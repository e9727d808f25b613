// `tumble simulate SCENE --csv FILE`: one CSV row per body per sample.
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "app/commands.hpp"
#include "app/stop_signals.hpp"
#include "core/error.hpp"
#include "core/propagator.hpp"
#include "scene/scene_run.hpp"
#include "io/atomic_file.hpp"
#include "io/trajectory_csv.hpp"

namespace tumble::app {

namespace {

struct SimulateOptions {
  std::string scene, csv, method;
  double dt = 0, duration = 0;
  long every = 0;
  CLI::Option *method_opt = nullptr, *dt_opt = nullptr, *duration_opt = nullptr, *every_opt = nullptr;
};

constexpr double kMaxRows = 1e8;  // guards --every 1 with a tiny dt

/// --method, --dt and --duration are scene keys: they go into the scene before
/// it is validated, so the loader's checks (dt <= duration, step cap, auto
/// with a tolerance) cover them and name the option.
std::vector<scene::Override> scene_overrides(const SimulateOptions& o) {
  std::vector<scene::Override> v;
  if (o.method_opt->count()) {
    v.push_back({"--method", "simulation.method", o.method});
    if (o.method != "auto") v.push_back({"--method", "simulation.tolerance", {}});  // the command line wins
  }
  if (o.dt_opt->count()) v.push_back({"--dt", "simulation.dt", o.dt});
  if (o.duration_opt->count()) v.push_back({"--duration", "simulation.duration", o.duration});
  return v;
}

/// What only `simulate` has: --every and the row cap.
void check_sampling(const SimulateOptions& o, const scene::Scene& s) {
  const scene::SimulationConfig& sim = s.simulation;
  if (o.every_opt->count() && sim.automatic && sim.tolerance)
    throw InputError("--every counts steps of the scene's dt, but method \"auto\" with a tolerance picks each body's dt; "
                     "drop --every (rows at the scene's fps) or add --method NAME");
  if (o.every_opt->count() && o.every < 1) throw InputError("--every: expected an integer >= 1, found " + std::to_string(o.every));
  const double samples = o.every_opt->count() ? sim.duration / (sim.step.dt * static_cast<double>(o.every))
                                              : sim.duration * sim.fps;
  if (samples * static_cast<double>(s.bodies.size()) > kMaxRows)
    throw InputError("the run would write more than 1e8 rows; raise --every or lower the scene's fps");
}

/// Each body's run with the method the scene (or auto) picks, saying why.
scene::SceneRun start_run(const scene::Scene& s) {
  scene::SceneRun run(s, s.simulation);
  for (std::size_t i = 0; i < run.size(); ++i) {
    const scene::BodyRun& b = run.body(i);
    if (!b.plan().reason.empty()) std::cerr << "tumble: body '" << b.body().name << "': auto picked " << b.plan().reason << "\n";
    if (auto w = b.warning()) std::cerr << "tumble: warning: " << *w << "\n";
  }
  return run;
}

/// Every row into `buf`: at t = 0, then every N steps (--every) or at the
/// scene's sample times; `after_sample` runs after each sample. Throws Diverged.
void write_rows(const SimulateOptions& o, const scene::Scene& s, scene::SceneRun& run, std::string& buf,
                const std::function<void()>& after_sample) {
  const auto row = [&](const scene::Sample& x) { io::append_simulate_row(buf, x.t, x.model, x.state); };
  if (o.every_opt->count()) return run.sample_every(o.every, s.simulation.duration, row, after_sample);
  run.sample(scene::sample_times(s.simulation.duration, s.simulation.fps), row, after_sample);
}

/// Where the rows go: the CSV file, written atomically, or standard output
/// for `--csv -` (the way to discard them, `> /dev/null`, since no output of
/// tumble's is written onto a device).
class RowSink {
 public:
  explicit RowSink(const std::string& csv) {
    if (csv != "-") file_ = std::make_unique<io::AtomicFile>(csv);
  }
  void write(std::string_view rows) {
    if (file_) return file_->write(rows);
    if (!std::cout.write(rows.data(), static_cast<std::streamsize>(rows.size())))
      throw io::IoError("cannot write the CSV to standard output");
  }
  void commit() {
    if (file_) return file_->commit();
    if (!std::cout.flush()) throw io::IoError("cannot write the CSV to standard output");
  }

 private:
  std::unique_ptr<io::AtomicFile> file_;
};

int run_simulate(const SimulateOptions& o) {
  const bool to_stdout = o.csv == "-";
  if (!to_stdout) io::check_output_file("--csv", o.csv);
  scene::Scene s = load_scene_verbose(o.scene, scene_overrides(o));
  if (!to_stdout) io::check_output_file("--csv", o.csv);  // again, now that the scene, clouds and meshes are known inputs
  check_sampling(o, s);
  scene::SceneRun run = start_run(s);
  // Ctrl-C / SIGTERM: stop at the next row, write nothing (the temp file goes
  // with `out`), and leave an existing CSV as it was.
  const StopSignals stop;
  struct Stopped {};
  RowSink out(o.csv);
  std::string buf = io::simulate_header() + "\n";
  auto flush = [&] {
    out.write(buf);
    buf.clear();
  };
  try {
    write_rows(o, s, run, buf, [&] {
      if (buf.size() > (1u << 20)) flush();
      if (stop.received()) throw Stopped{};
    });
  } catch (const Stopped&) {
    const int sig = stop.received();
    std::cerr << "tumble: interrupted (" << (sig == SIGINT ? "SIGINT" : "SIGTERM") << "): "
              << (to_stdout ? "the CSV on standard output stops short\n"
                            : "no CSV written; " + o.csv + " is as it was before the run\n");
    return 128 + sig;
  } catch (const Diverged& e) {
    // Keep what was computed: the rows up to the failure are valid.
    flush();
    out.commit();
    std::cerr << "tumble: " << e.what() << "\n"
              << "tumble: kept the rows computed before the failure " << (to_stdout ? "on standard output" : "in " + o.csv)
              << "\n";
    return kDiverged;
  }
  flush();
  out.commit();
  // The step each body actually took (fixed-step methods step on the grid n·dt).
  for (std::size_t i = 0; i < run.size(); ++i) {
    const Propagator& p = run.body(i).propagator();
    std::cerr << "tumble: body '" << p.model().name << "': " << method_name(p.config().method) << ", "
              << scene::step_label(p.config(), p.model()) << ", " << p.steps() << " steps\n";
  }
  return kOk;
}

}  // namespace

void add_simulate_command(CLI::App& app, Action& action) {
  const auto [cmd, o] = add_command(app, action, "simulate",
                                    "Integrate a scene and write a CSV of the states", run_simulate);
  cmd->add_option("--csv", o->csv, "Output CSV file (written atomically), or - for standard output")
      ->required()
      ->check(kPath);
  o->method_opt = cmd->add_option("--method", o->method, "auto or " + method_list());
  o->dt_opt = cmd->add_option("--dt", o->dt, "Step size, s (overrides the scene)");
  o->duration_opt = cmd->add_option("--duration", o->duration, "Run length, s (overrides the scene)");
  o->every_opt = cmd->add_option("--every", o->every, "Sample every N steps instead of at k/fps");
}

}  // namespace tumble::app
