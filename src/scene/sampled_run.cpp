#include "scene/sampled_run.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace tumble::scene {

const std::vector<const Observable*>& python_arrays() {
  static const std::vector<const Observable*> list = [] {
    std::vector<const Observable*> v;
    for (const Observable& o : observables())
      if (o.use & kPythonArray) v.push_back(&o);
    return v;
  }();
  return list;
}

const std::vector<double>& Trajectory::operator[](std::string_view name) const {
  for (std::size_t i = 0; i < python_arrays().size(); ++i)
    if (python_arrays()[i]->name == name) return arrays.at(i);
  throw std::out_of_range("scene::Trajectory: no array named " + std::string(name));
}

/// Every array's components, from the observables table (as the CSV's columns).
void append_sample(Trajectory& tr, double t, const RigidBodyModel& m, const BodyState& s) {
  tr.t.push_back(t);
  double v[kMaxComponents];
  for (std::size_t i = 0; i < python_arrays().size(); ++i) {
    const Observable& o = *python_arrays()[i];
    o.value(m, s, 0, v);
    tr.arrays[i].insert(tr.arrays[i].end(), v, v + o.size);
  }
}

Trajectory trajectory_header(const BodyRun& run) {
  Trajectory tr;
  tr.body = run.body().name;
  tr.method = std::string(method_name(run.plan().config.method));
  tr.step = step_label(run.plan().config, run.model());
  tr.auto_reason = run.plan().reason;
  return tr;
}

void check_sample_times(std::span<const double> times) {
  for (std::size_t k = 0; k < times.size(); ++k) {
    if (!std::isfinite(times[k]) || times[k] < 0)
      throw InputError("times[" + std::to_string(k) + "]: expected a finite time >= 0 s, found " +
                       std::to_string(times[k]));
    if (k > 0 && times[k] < times[k - 1])
      throw InputError("times[" + std::to_string(k) + "]: expected times in increasing order, found " +
                       std::to_string(times[k]) + " after " + std::to_string(times[k - 1]));
  }
}

std::vector<Trajectory> sample_run(const Scene& s, const SimulationConfig& sim, std::span<const double> times,
                                   const std::function<void()>& poll, const std::function<void(const std::string&)>& warn) {
  check_sample_times(times);
  SceneRun run(s, sim);
  std::vector<Trajectory> out;
  for (std::size_t i = 0; i < run.size(); ++i) {
    if (const auto w = run.body(i).warning(); w && warn) warn(*w);
    out.push_back(trajectory_header(run.body(i)));
  }
  run.sample(times, [&](const Sample& x) {
    append_sample(out[x.body], x.t, x.model, x.state);
    if (poll) poll();
  });
  for (std::size_t i = 0; i < run.size(); ++i) out[i].steps = run.body(i).steps();
  return out;
}

}  // namespace tumble::scene
