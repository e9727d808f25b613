// A scene's bodies integrated and sampled at given times, as arrays: what
// `tumble simulate` writes as CSV rows, kept for the Python module and the
// glTF export (one SceneRun and one observables table, so all agree to the
// last bit).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/observables.hpp"
#include "scene/scene_run.hpp"

namespace tumble::scene {

/// The observables a Trajectory keeps (kPythonArray), in its arrays' order.
const std::vector<const Observable*>& python_arrays();

/// One body's samples, in the CSV's units and frames: t and one array per
/// kPythonArray observable (core/observables.hpp). Arrays are row-major
/// (sample, component): "c" holds n×3 values, "q" n×4 (w, x, y, z).
struct Trajectory {
  std::string body;
  std::string method;       ///< the method that ran ("auto" resolved)
  std::string step;         ///< step_label: "dt = 0.001 s", "closed form", …
  std::string auto_reason;  ///< why "auto" picked it; empty when the scene named the method
  long steps = 0;           ///< steps taken (Propagator::steps)
  std::vector<double> t;    ///< s
  /// One per kPythonArray observable, in the table's order.
  std::vector<std::vector<double>> arrays = std::vector<std::vector<double>>(python_arrays().size());
  std::size_t size() const { return t.size(); }
  /// The array of observable `name` ("c", "q", "omega_body", …). Throws std::out_of_range for no such array.
  const std::vector<double>& operator[](std::string_view name) const;
};

/// A Trajectory with no samples: the body, method, step and auto's reason of `run`.
Trajectory trajectory_header(const BodyRun& run);

/// Appends the sample (t, state) of a body of model `m` to `tr` (every column).
void append_sample(Trajectory& tr, double t, const RigidBodyModel& m, const BodyState& s);

/// Throws InputError unless `times` are finite, >= 0 and non-decreasing.
void check_sample_times(std::span<const double> times);

/// Integrates every body of `s` (one SceneRun) and samples it at
/// `times` (s; a time at or before the last sample repeats it, as
/// Propagator::advance_to does). `poll`, when set, is called after each sample
/// of each body: it may throw to stop the run (Ctrl-C); `warn`, when set, gets
/// each body's BodyRun::warning before the bodies are stepped. Throws Diverged when a
/// body fails, InputError for bad times.
std::vector<Trajectory> sample_run(const Scene& s, const SimulationConfig& sim, std::span<const double> times,
                                   const std::function<void()>& poll = {},
                                   const std::function<void(const std::string&)>& warn = {});

}  // namespace tumble::scene
