#include "scene/sampled_run.hpp"

#include <cmath>
#include <string>

#include "core/dynamics.hpp"
#include "core/propagator.hpp"

namespace tumble::scene {

namespace {

void append(std::vector<double>& to, const Eigen::Vector3d& x) { to.insert(to.end(), {x.x(), x.y(), x.z()}); }

}  // namespace

/// The columns of io::append_trajectory_row and `simulate`'s extra ω_body, from the same functions.
void append_sample(Trajectory& tr, double t, const RigidBodyModel& m, const BodyState& s) {
  const Eigen::Quaterniond q = cloud_orientation(m, s);
  tr.t.push_back(t);
  append(tr.c, s.c);
  tr.q.insert(tr.q.end(), {q.w(), q.x(), q.y(), q.z()});
  append(tr.v, velocity(m, s));
  append(tr.omega_world, omega_world(m, s));
  append(tr.omega_body, omega_body(m, s));
  append(tr.L, s.L);
  tr.energy.push_back(total_energy(m, s));
}

BodyRun::BodyRun(const SimulationConfig& sim, const Body& body)
    : body_(&body), plan_(plan_method(sim, body)), p_(body.model, body.initial, plan_.config) {}

Trajectory BodyRun::header() const {
  Trajectory tr;
  tr.body = body_->name;
  tr.method = std::string(method_name(plan_.config.method));
  tr.step = step_label(plan_.config, body_->model);
  tr.auto_reason = plan_.reason;
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

std::optional<std::string> BodyRun::warning() const {
  return coarse_step_warning(body_->model, body_->initial, plan_.config);
}

std::vector<Trajectory> sample_run(const Scene& s, const SimulationConfig& sim, std::span<const double> times,
                                   const std::function<void()>& poll, const std::function<void(const std::string&)>& warn) {
  check_sample_times(times);
  std::vector<Trajectory> out;
  for (const Body& b : s.bodies) {
    BodyRun run(sim, b);
    if (const auto w = run.warning(); w && warn) warn(*w);
    Trajectory tr = run.header();
    for (double t : times) {
      append_sample(tr, t, b.model, run.at(t));
      if (poll) poll();
    }
    tr.steps = run.steps();
    out.push_back(std::move(tr));
  }
  return out;
}

}  // namespace tumble::scene
