#include "run/frame_renderer.hpp"

#include <algorithm>

#include "base/error.hpp"
#include "io/trajectory_csv.hpp"
#include "render/renderer.hpp"

namespace tumble::run {

SceneFrames::SceneFrames(const scene::Scene& s, long last_needed)
    : scene_(s), fps_(s.render.output.fps), count_(scene::frame_clock(s, s.render.output.fps).count()) {
  if (last_needed < 0 || last_needed >= count_)
    throw InputError("frame " + std::to_string(last_needed) + " is past the end of the scene (frames 0:" +
                     std::to_string(count_ - 1) + ")");
  // Laid-out views (a plot's value axis) also depend on the whole run.
  const long frames = s.render.camera.automatic || s.render.camera.across != 0 || !s.render.explain.views.empty()
                          ? count_
                          : last_needed + 1;
  runs_ = scene::simulate_runs(s, frames, fps_);
}

std::vector<io::Image> SceneFrames::render(render::GlContext& ctx, const std::vector<long>& ks,
                                           const scene::FrameSettings& f, int* samples_used) const {
  const compose::FrameBuilder builder(scene_, runs_, fps_, f.width, f.height);
  render::Renderer renderer(ctx, f.width, f.height, f.aa, f.msaa);
  if (samples_used) *samples_used = renderer.samples();
  std::vector<io::Image> out;
  for (long k : ks) {
    // A single run that diverged has no frame past the failure (`tumble render` stops there too).
    if (runs_.size() == 1 && k >= static_cast<long>(runs_[0].frames.size()))
      throw InputError("frame " + std::to_string(k) + " was not simulated" +
                       (runs_[0].diverged ? ": " + *runs_[0].diverged : std::string()));
    out.push_back(renderer.render(builder.build(k)));
  }
  return out;
}

std::string SceneFrames::trajectory_csv(const std::vector<long>& ks) const {
  std::string out = io::trajectory_header() + "\n";
  const scene::FrameClock clock = scene::frame_clock(scene_, fps_);
  for (long k : ks) {
    for (const scene::Run& run : runs_) {
      if (k >= static_cast<long>(run.frames.size())) continue;  // diverged: the row count shows it
      const auto& states = run.frames[static_cast<std::size_t>(k)];
      for (std::size_t i = 0; i < states.size() && i < scene_.bodies.size(); ++i) {
        const RigidBodyModel& m = scene_.bodies[i].model;
        io::append_trajectory_row(out, clock.time(k), runs_.size() > 1 ? run.label + ":" + m.name : m.name,
                                  m, states[i]);
      }
    }
  }
  return out;
}

}  // namespace tumble::run
