#include "scene/frame_runs.hpp"

#include <algorithm>
#include <cmath>

#include "core/dynamics.hpp"
#include "core/error.hpp"
#include "scene/scene_run.hpp"

namespace tumble::scene {

int sub_samples(const std::vector<const RigidBodyModel*>& models, const std::vector<BodyState>& states, double h) {
  double turn = 0;  // rad, the largest turn of any body over h
  for (std::size_t b = 0; b < states.size() && b < models.size(); ++b)
    turn = std::max(turn, omega_world(*models[b], states[b]).norm() * h);
  if (!std::isfinite(turn)) return 1;
  return static_cast<int>(std::clamp(std::ceil(turn / kMaxTurnPerSample), 1.0, static_cast<double>(kMaxSubSamples)));
}

namespace {

// The run's notes, energies at t = 0 and labels. Labels list each method and
// step once, compared whole (by enum for the methods): rk45 and rk4 are two
// entries, not one substring of the other.
void label_run(const SceneRun& bodies, Run& run) {
  std::vector<Method> used;
  std::vector<std::string> steps;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const Body& b = bodies.body(i).body();
    const MethodPlan& plan = bodies.body(i).plan();
    if (!plan.reason.empty()) run.auto_notes.push_back("body '" + b.name + "': auto picked " + plan.reason);
    if (auto w = bodies.body(i).warning()) run.auto_notes.push_back("warning: " + *w);
    run.energy0.push_back(total_energy(b.model, b.initial));
    const std::string step = step_label(plan.config, b.model);
    if (std::find(steps.begin(), steps.end(), step) == steps.end()) {
      steps.push_back(step);
      run.step_label += (run.step_label.empty() ? "" : "/") + step;
    }
    if (std::find(used.begin(), used.end(), plan.config.method) == used.end()) {
      used.push_back(plan.config.method);
      run.label += (run.label.empty() ? "" : "/") + std::string(method_name(plan.config.method));
      const MethodInfo& info = method_info(plan.config.method);
      run.title += (run.title.empty() ? "" : " / ") + std::string(info.title) +
                   (info.order > 0 ? ", order " + std::to_string(info.order) : "");
    }
  }
}

// The run's frames (and, with `curves`, its path: the frames and sub-frame
// samples between them) until the last frame or a divergence.
void advance_run(const FrameClock& clock, long frames, bool curves, const std::vector<const RigidBodyModel*>& models,
                 SceneRun& bodies, Run& run) {
  try {
    for (long k = 0; k < frames; ++k) {
      const double t = clock.time(k);
      if (curves && k > 0) {
        // Sub-frame samples: dense output between grid points, never fed
        // back, so the frames are the same with or without them.
        const double t0 = clock.time(k - 1);
        const int n = sub_samples(models, run.frames.back(), t - t0);
        for (int j = 1; j < n; ++j) {
          const double tj = t0 + (t - t0) * j / n;
          run.path.push_back(bodies.states_at(tj));
          run.path_t.push_back(tj);
        }
      }
      std::vector<BodyState> states = bodies.states_at(t);
      if (curves) {
        run.path_of_frame.push_back(run.path.size());
        run.path.push_back(states);
        run.path_t.push_back(t);
      }
      run.frames.push_back(std::move(states));
    }
  } catch (const Diverged& e) {
    run.diverged = e.what();
  }
}

}  // namespace

std::vector<Run> simulate_runs(const Scene& s, long frames, double fps) {
  std::vector<std::optional<Method>> methods;
  for (Method m : s.render.compare_methods) methods.push_back(m);
  if (methods.empty()) methods.push_back(s.simulation.automatic ? std::nullopt : std::optional(s.simulation.step.method));
  const FrameClock clock = frame_clock(s, fps);
  const bool curves = s.render.draw.trail_seconds > 0 || !s.render.explain.views.empty();
  std::vector<const RigidBodyModel*> models;
  for (const Body& b : s.bodies) models.push_back(&b.model);
  std::vector<Run> runs;
  for (const auto& method : methods) {
    Run run;
    SimulationConfig sim = s.simulation;
    sim.automatic = !method;
    if (method) sim.step.method = *method;
    for (const auto& [m, dt] : s.render.compare_steps)  // the method's own step ([compare] steps)
      if (method && m == *method) sim.step.dt = dt;
    SceneRun bodies(s, sim);
    label_run(bodies, run);
    advance_run(clock, frames, curves, models, bodies, run);
    runs.push_back(std::move(run));
  }
  return runs;
}

}  // namespace tumble::scene
