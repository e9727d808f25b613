// One run of a scene's bodies: each body stepped from t = 0 with
// plan_method(sim, body), its samples handed to whoever asks. The frames,
// `tumble simulate`'s CSV, the Python arrays and the glTF keys all step
// through here, so they agree to the last bit.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/propagator.hpp"
#include "scene/scene.hpp"

namespace tumble::scene {

/// One body stepped from t = 0 with plan_method(sim, body) and sampled on
/// request, for callers that pick the next sample time from the last state
/// (the glTF export's keys).
class BodyRun {
 public:
  BodyRun(const SimulationConfig& sim, const Body& body);
  /// The state at t (s): a time at or before the last sample repeats it, as
  /// Propagator::advance_to does. Throws Diverged.
  const BodyState& at(double t) { return p_.advance_to(t); }
  /// Exactly n more steps of dt (`tumble simulate --every`). Throws Diverged.
  const BodyState& after_steps(long n) { return p_.advance_steps(n); }
  const Body& body() const { return *body_; }
  const RigidBodyModel& model() const { return body_->model; }
  const MethodPlan& plan() const { return plan_; }
  const Propagator& propagator() const { return p_; }
  long steps() const { return p_.steps(); }
  /// The command line's warning when dt is too coarse for the body's start (core::coarse_step_warning).
  std::optional<std::string> warning() const;

 private:
  const Body* body_;
  MethodPlan plan_;
  Propagator p_;
};

/// One sample: body `body` (its index in the scene) in `state` at time t (s).
struct Sample {
  double t;
  std::size_t body;
  const RigidBodyModel& model;
  const BodyState& state;
};
using SampleSink = std::function<void(const Sample&)>;

/// Every body of a scene, stepped together: a sample time hands each body's
/// state to the sink in body order. A body that diverges throws Diverged
/// after the bodies before it were handed over.
class SceneRun {
 public:
  SceneRun(const Scene& s, const SimulationConfig& sim);
  std::size_t size() const { return bodies_.size(); }
  BodyRun& body(std::size_t i) { return *bodies_[i]; }
  const BodyRun& body(std::size_t i) const { return *bodies_[i]; }

  /// Every body at time t (s).
  void sample(double t, const SampleSink& sink);
  /// Every body at each of `times` (s) in turn; `after_time`, when set, runs
  /// after each time's samples (it may throw to stop the run).
  void sample(std::span<const double> times, const SampleSink& sink, const std::function<void()>& after_time = {});
  /// t = 0, then every n steps of the scene's dt up to `duration` (s): the
  /// block that ends within round-off of the end lands on it exactly.
  void sample_every(long n, double duration, const SampleSink& sink, const std::function<void()>& after_time = {});
  /// Every body's state at t (s), in body order.
  std::vector<BodyState> states_at(double t);

 private:
  double dt_;
  std::vector<std::unique_ptr<BodyRun>> bodies_;
};

}  // namespace tumble::scene
