// A scene's bodies integrated and sampled at given times, as columns: what
// `tumble simulate` writes as CSV rows, kept as arrays for the Python module
// and the glTF export (one loop, so all three agree to the last bit).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/propagator.hpp"
#include "scene/scene.hpp"

namespace tumble::scene {

/// One body's samples, in the CSV's units and frames. Vectors are row-major
/// (sample, component): `c` holds n×3 values, `q` n×4 (w, x, y, z).
struct Trajectory {
  std::string body;
  std::string method;       ///< the method that ran ("auto" resolved)
  std::string step;         ///< step_label: "dt = 0.001 s", "closed form", …
  std::string auto_reason;  ///< why "auto" picked it; empty when the scene named the method
  long steps = 0;           ///< steps taken (Propagator::steps)
  std::vector<double> t;            ///< s
  std::vector<double> c;            ///< centre of mass, world, m
  std::vector<double> q;            ///< world ← cloud orientation (w, x, y, z)
  std::vector<double> v;            ///< velocity of c, world, m/s
  std::vector<double> omega_world;  ///< rad/s, world frame
  std::vector<double> omega_body;   ///< rad/s, the cloud's own axes
  std::vector<double> L;            ///< angular momentum about c, world, kg·m²/s
  std::vector<double> energy;       ///< total energy, J
  std::size_t size() const { return t.size(); }
};

/// One body stepped from t = 0 with plan_method(sim, body) and sampled on
/// request: the loop behind sample_run, for callers that pick the next sample
/// time from the last state (the glTF export's keys).
class BodyRun {
 public:
  BodyRun(const SimulationConfig& sim, const Body& body);
  /// The state at t (s): a time at or before the last sample repeats it, as
  /// Propagator::advance_to does. Throws Diverged.
  const BodyState& at(double t) { return t <= p_.time() ? p_.state() : p_.advance_to(t); }
  const RigidBodyModel& model() const { return body_->model; }
  /// A Trajectory with no samples: the body, method, step and auto's reason.
  Trajectory header() const;
  long steps() const { return p_.steps(); }
  /// The command line's warning when dt is too coarse for the body's start (core::coarse_step_warning).
  std::optional<std::string> warning() const;

 private:
  const Body* body_;
  MethodPlan plan_;
  Propagator p_;
};

/// Appends the sample (t, state) of a body of model `m` to `tr` (every column).
void append_sample(Trajectory& tr, double t, const RigidBodyModel& m, const BodyState& s);

/// Throws InputError unless `times` are finite, >= 0 and non-decreasing.
void check_sample_times(std::span<const double> times);

/// Integrates every body of `s` with plan_method(sim, body) and samples it at
/// `times` (s; a time at or before the last sample repeats it, as
/// Propagator::advance_to does). `poll`, when set, is called after each sample
/// of each body: it may throw to stop the run (Ctrl-C); `warn`, when set, gets
/// each body's BodyRun::warning before it is stepped. Throws Diverged when a
/// body fails, InputError for bad times.
std::vector<Trajectory> sample_run(const Scene& s, const SimulationConfig& sim, std::span<const double> times,
                                   const std::function<void()>& poll = {},
                                   const std::function<void(const std::string&)>& warn = {});

}  // namespace tumble::scene
