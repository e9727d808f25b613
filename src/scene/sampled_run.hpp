// A scene's bodies integrated and sampled at given times, as columns: what
// `tumble simulate` writes as CSV rows, kept as arrays for the Python module
// and the glTF export (one loop, so all three agree to the last bit).
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <vector>

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

/// Throws InputError unless `times` are finite, >= 0 and non-decreasing.
void check_sample_times(std::span<const double> times);

/// Integrates every body of `s` with plan_method(sim, body) and samples it at
/// `times` (s; a time at or before the last sample repeats it, as
/// Propagator::advance_to does). `poll`, when set, is called after each sample
/// of each body: it may throw to stop the run (Ctrl-C). Throws Diverged when a
/// body fails, InputError for bad times.
std::vector<Trajectory> sample_run(const Scene& s, const SimulationConfig& sim, std::span<const double> times,
                                   const std::function<void()>& poll = {});

}  // namespace tumble::scene
