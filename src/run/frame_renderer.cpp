#include "app/frame_renderer.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/error.hpp"
#include "io/trajectory_csv.hpp"
#include "render/renderer.hpp"

namespace tumble::app {

std::string AaSetting::name() const {
  if (mode == scene::Antialias::fxaa) return "fxaa";
  return "msaa" + std::to_string(samples());
}

AaSetting aa_setting(const scene::OutputConfig& out) { return {out.aa, out.msaa}; }

AaSetting parse_aa_setting(const std::string& text, const std::string& option) {
  if (text == "fxaa") return {scene::Antialias::fxaa, 0};
  if (text == "none" || text == "msaa0") return {scene::Antialias::none, 0};
  if (text == "msaa2" || text == "msaa4") return {scene::Antialias::msaa, text.back() - '0'};
  throw InputError(option + ": expected fxaa, none, msaa0, msaa2 or msaa4, found '" + text + "'");
}

render::GlBackend parse_backend_option(const std::string& gl) {
  const std::string where = gl.empty() ? "TUMBLE_GL" : "--gl";
  try {
    return gl.empty() ? render::default_gl_backend() : render::parse_gl_backend(gl);
  } catch (const std::invalid_argument& e) {
    throw InputError(where + ": " + e.what());
  }
}

SceneFrames::SceneFrames(const scene::Scene& s, long last_needed)
    : scene_(s), fps_(s.render.output.fps), count_(scene::frame_clock(s, s.render.output.fps).count()) {
  if (last_needed < 0 || last_needed >= count_)
    throw InputError("frame " + std::to_string(last_needed) + " is past the end of the scene (frames 0:" +
                     std::to_string(count_ - 1) + ")");
  // Laid-out views (a plot's value axis) also depend on the whole run.
  const long frames = s.render.camera.automatic || !s.render.explain.views.empty() ? count_ : last_needed + 1;
  runs_ = simulate_runs(s, frames, fps_);
}

std::vector<io::Image> SceneFrames::render(render::GlContext& ctx, const std::vector<long>& ks, int width,
                                           int height, AaSetting aa, int* samples_used) const {
  const FrameBuilder builder(scene_, runs_, fps_, width, height);
  render::Renderer renderer(ctx, width, height, aa.samples(), aa.fxaa());
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
  std::string out = std::string(io::kTrajectoryHeader) + "\n";
  const scene::FrameClock clock = scene::frame_clock(scene_, fps_);
  for (long k : ks) {
    for (const Run& run : runs_) {
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

}  // namespace tumble::app
