#include "scene/scene_run.hpp"

#include <cmath>

namespace tumble::scene {

BodyRun::BodyRun(const SimulationConfig& sim, const Body& body)
    : body_(&body), plan_(plan_method(sim, body)), p_(body.model, body.initial, plan_.config) {}

std::optional<std::string> BodyRun::warning() const {
  return coarse_step_warning(body_->model, body_->initial, plan_.config);
}

SceneRun::SceneRun(const Scene& s, const SimulationConfig& sim) : dt_(sim.step.dt) {
  for (const Body& b : s.bodies) bodies_.push_back(std::make_unique<BodyRun>(sim, b));
}

void SceneRun::sample(double t, const SampleSink& sink) {
  for (std::size_t i = 0; i < bodies_.size(); ++i) sink({t, i, bodies_[i]->model(), bodies_[i]->at(t)});
}

void SceneRun::sample(std::span<const double> times, const SampleSink& sink, const std::function<void()>& after_time) {
  for (double t : times) {
    sample(t, sink);
    if (after_time) after_time();
  }
}

void SceneRun::sample_every(long n, double duration, const SampleSink& sink, const std::function<void()>& after_time) {
  sample(0.0, sink);
  const double every = static_cast<double>(n);
  const long blocks = static_cast<long>(std::floor(duration / (dt_ * every) * (1 + 1e-12)));
  for (long b = 1; b <= blocks + 1; ++b) {
    const bool last = static_cast<double>(b) * every * dt_ >= duration * (1 - 1e-12);
    const double t = last ? duration : static_cast<double>(b) * every * dt_;
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      BodyRun& r = *bodies_[i];
      sink({t, i, r.model(), last ? r.at(duration) : r.after_steps(n)});
    }
    if (after_time) after_time();
    if (last) break;
  }
}

std::vector<BodyState> SceneRun::states_at(double t) {
  std::vector<BodyState> out;
  sample(t, [&](const Sample& x) { out.push_back(x.state); });
  return out;
}

}  // namespace tumble::scene
