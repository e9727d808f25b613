// `tumble simulate SCENE --csv FILE`: one CSV row per body per sample.
#include <cmath>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "app/commands.hpp"
#include "app/stop_signals.hpp"
#include "core/propagator.hpp"
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

using Propagators = std::vector<std::unique_ptr<Propagator>>;

/// Each body's propagator with the method the scene (or auto) picks, saying why.
Propagators make_propagators(const scene::Scene& s) {
  Propagators props;
  for (const scene::Body& b : s.bodies) {
    const scene::MethodPlan plan = scene::plan_method(s.simulation, b);
    if (!plan.reason.empty()) std::cerr << "tumble: body '" << b.name << "': auto picked " << plan.reason << "\n";
    if (auto w = coarse_step_warning(b.model, b.initial, plan.config)) std::cerr << "tumble: warning: " << *w << "\n";
    props.push_back(std::make_unique<Propagator>(b.model, b.initial, plan.config));
  }
  return props;
}

/// The rows after t = 0 into `buf`: every N steps (--every) or at the scene's
/// sample times; `after_sample` runs after each sample. Throws Diverged.
void step_rows(const SimulateOptions& o, const scene::Scene& s, Propagators& props, std::string& buf,
               const std::function<void()>& after_sample) {
  const double duration = s.simulation.duration, dt = s.simulation.step.dt;
  if (o.every_opt->count()) {
    // Every N steps; the block that ends within round-off of the end lands on it exactly.
    const double n = static_cast<double>(o.every);
    const long blocks = static_cast<long>(std::floor(duration / (dt * n) * (1 + 1e-12)));
    for (long b = 1; b <= blocks + 1; ++b) {
      const bool last = static_cast<double>(b) * n * dt >= duration * (1 - 1e-12);
      for (auto& p : props) {
        const BodyState& st = last ? p->advance_to(duration) : p->advance_steps(o.every);
        io::append_simulate_row(buf, last ? duration : static_cast<double>(b) * n * dt, p->model(), st);
      }
      after_sample();
      if (last) break;
    }
  } else {
    const std::vector<double> times = scene::sample_times(duration, s.simulation.fps);
    for (std::size_t k = 1; k < times.size(); ++k) {
      for (auto& p : props) io::append_simulate_row(buf, times[k], p->model(), p->advance_to(times[k]));
      after_sample();
    }
  }
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
  Propagators props = make_propagators(s);
  // Ctrl-C / SIGTERM: stop at the next row, write nothing (the temp file goes
  // with `out`), and leave an existing CSV as it was.
  const StopSignals stop;
  struct Stopped {};
  RowSink out(o.csv);
  std::string buf = std::string(io::kTrajectoryHeader) + io::kSimulateExtraColumns + "\n";
  auto flush = [&] {
    out.write(buf);
    buf.clear();
  };
  try {
    for (auto& p : props) io::append_simulate_row(buf, 0.0, p->model(), p->state());
    step_rows(o, s, props, buf, [&] {
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
  for (const auto& p : props)
    std::cerr << "tumble: body '" << p->model().name << "': " << method_name(p->config().method) << ", "
              << scene::step_label(p->config(), p->model()) << ", " << p->steps() << " steps\n";
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
