#include "run/render_job.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "core/dynamics.hpp"
#include "core/error.hpp"
#include "core/propagator.hpp"
#include "run/explain_views.hpp"
#include "viz/captions.hpp"
#include "viz/text_layout.hpp"
#include "viz/particle_set.hpp"

namespace tumble::run {

std::pair<long, long> parse_frame_range(const std::string& spec, long count) {
  const auto colon = spec.find(':');
  if (colon == std::string::npos) throw InputError("--frames: expected A:B (inclusive frame numbers), found '" + spec + "'");
  auto num = [&](const std::string& s, long dflt) -> long {
    if (s.empty()) return dflt;
    size_t used = 0;
    long v = -1;
    try {
      v = std::stol(s, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != s.size() || v < 0) throw InputError("--frames: expected a frame number >= 0, found '" + s + "'");
    return v;
  };
  const long a = num(spec.substr(0, colon), 0), b = num(spec.substr(colon + 1), count - 1);
  if (a > b)
    throw InputError("--frames " + spec + ": the first frame (" + std::to_string(a) + ") is after the last (" +
                     std::to_string(b) + "); expected A <= B");
  if (b >= count)
    throw InputError("--frames " + spec + ": the scene has frames 0:" + std::to_string(count - 1));
  return {a, b};
}

int sub_samples(const std::vector<const RigidBodyModel*>& models, const std::vector<BodyState>& states, double h) {
  double turn = 0;  // rad, the largest turn of any body over h
  for (std::size_t b = 0; b < states.size() && b < models.size(); ++b)
    turn = std::max(turn, omega_world(*models[b], states[b]).norm() * h);
  if (!std::isfinite(turn)) return 1;
  return static_cast<int>(std::clamp(std::ceil(turn / kMaxTurnPerSample), 1.0, static_cast<double>(kMaxSubSamples)));
}

namespace {

using Propagators = std::vector<std::unique_ptr<Propagator>>;

// One Propagator per body for `sim`, with the run's notes, energies at t = 0
// and labels. Labels list each method and step once, compared whole (by enum
// for the methods): rk45 and rk4 are two entries, not one substring of the other.
Propagators start_run(const scene::Scene& s, const scene::SimulationConfig& sim, Run& run) {
  Propagators props;
  std::vector<Method> used;
  std::vector<std::string> steps;
  for (const scene::Body& b : s.bodies) {
    const scene::MethodPlan plan = scene::plan_method(sim, b);
    if (!plan.reason.empty()) run.auto_notes.push_back("body '" + b.name + "': auto picked " + plan.reason);
    if (auto w = coarse_step_warning(b.model, b.initial, plan.config)) run.auto_notes.push_back("warning: " + *w);
    props.push_back(std::make_unique<Propagator>(b.model, b.initial, plan.config));
    run.energy0.push_back(total_energy(b.model, b.initial));
    const std::string step = scene::step_label(plan.config, b.model);
    if (std::find(steps.begin(), steps.end(), step) == steps.end()) {
      steps.push_back(step);
      run.step_label += (run.step_label.empty() ? "" : "/") + step;
    }
    if (std::find(used.begin(), used.end(), plan.config.method) == used.end()) {
      used.push_back(plan.config.method);
      run.label += (run.label.empty() ? "" : "/") + std::string(method_name(plan.config.method));
    }
  }
  return props;
}

// The run's frames (and, with `curves`, its path: the frames and sub-frame
// samples between them) until the last frame or a divergence.
void advance_run(const scene::FrameClock& clock, long frames, bool curves, const std::vector<const RigidBodyModel*>& models,
                 Propagators& props, Run& run) {
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
          std::vector<BodyState> sub;
          for (auto& p : props) sub.push_back(p->advance_to(tj));
          run.path.push_back(std::move(sub));
          run.path_t.push_back(tj);
        }
      }
      std::vector<BodyState> states;
      for (auto& p : props) states.push_back(p->advance_to(t));
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

std::vector<Run> simulate_runs(const scene::Scene& s, long frames, double fps) {
  std::vector<std::optional<Method>> methods;
  for (Method m : s.render.compare_methods) methods.push_back(m);
  if (methods.empty()) methods.push_back(s.simulation.automatic ? std::nullopt : std::optional(s.simulation.step.method));
  const scene::FrameClock clock = scene::frame_clock(s, fps);
  const bool curves = s.render.draw.trails > 0 || !s.render.explain.views.empty();
  std::vector<const RigidBodyModel*> models;
  for (const scene::Body& b : s.bodies) models.push_back(&b.model);
  std::vector<Run> runs;
  for (const auto& method : methods) {
    Run run;
    scene::SimulationConfig sim = s.simulation;
    sim.automatic = !method;
    if (method) sim.step.method = *method;
    Propagators props = start_run(s, sim, run);
    advance_run(clock, frames, curves, models, props, run);
    runs.push_back(std::move(run));
  }
  return runs;
}

namespace {

viz::Color rgba(const Eigen::Vector3d& c, float a) {
  return {static_cast<float>(c.x()), static_cast<float>(c.y()), static_cast<float>(c.z()), a};
}
glm::dvec3 to_glm(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

std::vector<viz::BodySnapshot> snapshots(const scene::Scene& s, const std::vector<BodyState>& states,
                                         const std::vector<viz::BodyLook>* looks = nullptr) {
  std::vector<viz::BodySnapshot> out;
  for (size_t i = 0; i < s.bodies.size() && i < states.size(); ++i)
    out.push_back({&s.bodies[i].model, &s.bodies[i].cloud, states[i], rgba(s.bodies[i].color, 0.38f),
                   looks ? &(*looks)[i] : nullptr, s.bodies[i].label});
  return out;
}

// Body names beside the bodies: screen text, so they always face the camera.
// Each names its body's box on screen (subject_px): viz::settle_labels keeps it beside, not on, the box.
void add_labels(viz::View& v, const std::vector<viz::BodySnapshot>& snaps, const viz::DrawOptions& draw, int width_px,
                int height_px, float font_px) {
  const float fw = static_cast<float>(width_px), fh = static_cast<float>(height_px);
  for (const viz::BodySnapshot& b : snaps) {
    const glm::dvec3 above = to_glm(b.state.c) + glm::normalize(v.camera.up) * (1.1 * viz::box_radius(*b.model));
    glm::vec2 px;
    const auto box = viz::screen_box(v.camera, fw, fh, viz::box_corners(viz::body_box(b, draw)));
    if (!box || !viz::project_to_viewport(v.camera, width_px, height_px, above, px)) continue;  // none for what is out of view
    const std::string& shown = b.label.empty() ? b.model->name : b.label;
    const float w = viz::approx_text_width(shown, font_px * 1.1f);
    v.texts.push_back({shown, {px.x - 0.5f * w, px.y - 1.2f * font_px}, font_px * 1.1f, {0.1f, 0.1f, 0.14f, 1.0f},
                       "label:" + b.model->name});
    v.texts.back().subject_px = {box->x0, box->y0, box->x1, box->y1};
  }
}

// Once per body: mesh surfaces, the particles that can be seen, part colours.
viz::BodyLook body_look(const scene::Body& b, bool particles) {
  viz::BodyLook look;
  for (const scene::MeshSource& m : b.meshes) {
    if (m.surface.triangles.empty()) continue;
    look.surfaces.push_back(viz::make_surface(m.surface));
    look.surface_colors.push_back(rgba(m.color, 1.0f));
  }
  for (const scene::ShapeSource& sh : b.shapes) {
    look.surfaces.push_back(viz::solid_surface(sh.shape));
    look.surface_colors.push_back(rgba(sh.color, 1.0f));
  }
  if (!look.surfaces.empty())
    look.surface_box = viz::principal_extent(look.surfaces, b.model.cloud_from_principal.toRotationMatrix(), b.model.com_cloud);
  if (!particles) return look;
  std::vector<viz::Color> colors;
  colors.reserve(b.cloud.size());
  for (std::size_t i = 0; i < b.cloud.size(); ++i) {
    Eigen::Vector3d c = b.color;
    for (const scene::ColorSpan& span : b.part_colors)
      if (i >= span.begin && i < span.end) c = span.color;
    colors.push_back(rgba(0.75 * c, 1.0f));
  }
  look.particles = viz::make_particle_set(b.cloud, colors, static_cast<float>(viz::particle_radius(b.model)));
  return look;
}

// The overlay line: time, method, step, energy error, as the scene's overlay asks.
std::string overlay_line(const scene::OverlayItems& items, const Run& run, std::size_t run_count,
                         const std::vector<viz::BodySnapshot>& snaps, double t) {
  // Largest relative energy error over the bodies: the failure users look
  // for. Only where energy is conserved (gravity is in it, as potential):
  // a thruster, torque or damping does work, and its change is no error.
  double rel = 0;
  bool conserved = true;
  for (size_t i = 0; i < snaps.size(); ++i) {
    conserved = conserved && snaps[i].model->forces.conserves_energy();
    const double e0 = run.energy0[i];
    const double e = total_energy(*snaps[i].model, snaps[i].state);
    rel = std::max(rel, std::abs(e - e0) / std::max(std::abs(e0), 1e-300));
  }
  // In a comparison grid the label names the method; keep the line short
  // and the font in proportion to the viewport.
  // Below 1e-13 the digits are round-off: they would change with the
  // compiler and break golden images for no physical reason.
  char energy[40];
  if (!conserved) std::snprintf(energy, sizeof energy, "(forces do work)");
  else if (rel < 1e-13) std::snprintf(energy, sizeof energy, "|dE/E| < 1e-13");
  else std::snprintf(energy, sizeof energy, "|dE/E| = %.1e", rel);
  char time[40];
  if (run_count > 1) std::snprintf(time, sizeof time, "t = %.2f s", t);
  else std::snprintf(time, sizeof time, "t = %6.2f s", t);
  std::string line;
  auto part = [&](bool on, const std::string& text) {
    if (on) line += (line.empty() ? "" : "   ") + text;
  };
  part(items.time, time);
  part(items.method && run_count == 1, run.label);
  part(items.step, run.step_label);
  part(items.energy, energy);
  return line;
}

}  // namespace

viz::DrawOptions draw_options(const scene::DrawConfig& d) {
  viz::DrawOptions o;
  o.box = d.box, o.surface = d.surface, o.axes = d.axes, o.particles = d.particles;
  o.angular_momentum = d.L, o.omega = d.omega, o.trail_seconds = d.trails, o.grid = d.grid;
  return o;
}

viz::Camera scene_camera(const scene::Scene& s, const std::vector<Run>& runs, double aspect) {
  const scene::CameraConfig& c = s.render.camera;
  viz::Camera camera;
  if (c.automatic) {
    // Frame every body over the whole run (all runs: a failing method may drift).
    std::vector<glm::dvec3> centres;
    std::vector<double> radii;
    for (const Run& r : runs)
      for (const auto& states : r.frames)
        for (size_t i = 0; i < states.size(); ++i) {
          if (!states[i].c.allFinite() || states[i].c.norm() > 1e6) continue;
          centres.push_back(to_glm(states[i].c));
          radii.push_back(viz::box_radius(s.bodies[i].model) * 1.15);
        }
    return viz::auto_camera(centres, radii, c.fov_y_deg, aspect);
  }
  camera.position = to_glm(c.position);
  camera.target = to_glm(c.target);
  camera.up = to_glm(c.up);
  camera.fov_y_deg = c.fov_y_deg;
  return camera;
}

viz::GridItem ground_grid(const scene::Scene& s, const std::vector<Run>& runs) {
  // Fixed for the whole video: below the lowest any body comes, centred
  // under where the bodies go, wide enough for all of it (0.5 m squares, or
  // finer for small bodies).
  double zmin = 1e300, size = 0;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = Eigen::Vector3d::Constant(-1e300);
  for (const Run& r : runs)
    for (const auto& states : r.frames)
      for (std::size_t i = 0; i < states.size() && i < s.bodies.size(); ++i) {
        if (!states[i].c.allFinite() || states[i].c.norm() > 1e6) continue;
        const double rad = viz::box_radius(s.bodies[i].model);
        zmin = std::min(zmin, states[i].c.z() - rad);
        lo = lo.cwiseMin(states[i].c), hi = hi.cwiseMax(states[i].c);
        size = std::max(size, rad);
      }
  if (zmin > 1e299) return {{0, 0, 0}, 0.5, 20, {0.5f, 0.52f, 0.58f, 0.5f}};
  const double spacing = std::clamp(std::pow(10.0, std::floor(std::log10(std::max(size, 1e-6)))), 1e-3, 0.5);
  const double reach = 0.5 * (hi - lo).head<2>().norm() + 6 * size;
  const int half = static_cast<int>(std::clamp(std::ceil(reach / spacing), 4.0, 200.0));
  const Eigen::Vector3d mid = 0.5 * (lo + hi);
  return {{spacing * std::round(mid.x() / spacing), spacing * std::round(mid.y() / spacing), zmin}, spacing, half,
          {0.5f, 0.52f, 0.58f, 0.5f}};
}

FrameBuilder::~FrameBuilder() = default;

FrameBuilder::FrameBuilder(const scene::Scene& s, const std::vector<Run>& runs, double fps, int width, int height)
    : scene_(s), runs_(runs), fps_(fps), clock_(scene::frame_clock(s, fps)), width_(width), height_(height) {
  const int n = std::max<int>(1, static_cast<int>(runs.size()));
  columns_ = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
  rows_ = (n + columns_ - 1) / columns_;
  // Explanatory views: the label size of the text roles (in proportion to the frame).
  font_px_ = s.render.explain.views.empty() ? std::clamp(static_cast<float>(height) / rows_ / 24.0f, 11.0f, 18.0f)
                                            : viz::text_px(viz::TextRole::label, height);
  const scene::DrawConfig& d = s.render.draw;
  draw_ = draw_options(d);
  for (const scene::Body& b : s.bodies) looks_.push_back(body_look(b, d.particles));
  const double aspect = (static_cast<double>(width) / columns_) / (static_cast<double>(height) / rows_);
  camera_ = scene_camera(s, runs, aspect);
  // Trails see every frame from t = 0, so a frame range draws what a full run does.
  trails_.resize(runs.size());
  if (draw_.trail_seconds > 0)
    for (size_t r = 0; r < runs.size(); ++r)
      for (size_t j = 0; j < runs[r].path.size(); ++j)
        trails_[r].record(runs[r].path_t[j], snapshots(s, runs[r].path[j]));
  grid_ = ground_grid(s, runs);
  if (!s.render.explain.views.empty() || !s.render.explain.captions.empty() || s.render.explain.title.hold > 0)
    explain_ = std::make_unique<ExplainViews>(*this, s, runs, width, height);
}

viz::View FrameBuilder::world_view(std::size_t r, long k, const viz::Camera& camera, int width_px,
                                   int height_px, float top_px, std::optional<std::size_t> only_body) const {
  const double t = clock_.time(k);
  const viz::Color ink{0.12f, 0.13f, 0.16f, 1.0f};
  const Run& run = runs_[r];
  viz::View v;
  v.camera = camera;
  v.label = runs_.size() > 1 ? run.label : "";
  const long last = static_cast<long>(run.frames.size()) - 1;
  const long kk = std::min(k, last);
  if (kk >= 0) {
    auto snaps = snapshots(scene_, run.frames[static_cast<size_t>(kk)], &looks_);
    if (only_body && *only_body < snaps.size()) snaps = {snaps[*only_body]};
    const scene::Body* follow = scene_.find_body(scene_.render.camera.follow);
    if (follow) {
      const glm::dvec3 c = to_glm(run.frames[static_cast<size_t>(kk)][static_cast<size_t>(follow - scene_.bodies.data())].c);
      v.camera.position += c - v.camera.target;
      v.camera.target = c;
    }
    viz::add_bodies(v, snaps, draw_, &trails_[r], clock_.time(kk));
    if (draw_.grid) v.grids.push_back(grid_);
    const std::size_t labels_begin = v.texts.size();
    if (scene_.render.explain.labels) add_labels(v, snaps, draw_, width_px, height_px, font_px_);
    const std::size_t labels_end = v.texts.size();
    if (scene_.render.draw.overlay) {
      const std::string line = overlay_line(scene_.render.draw.overlay_items, run, runs_.size(), snaps, t);
      const float y = top_px + (runs_.size() > 1 ? 30.0f : 12.0f);
      v.texts.push_back({line, {12.0f, y}, font_px_, ink});
      // Name labels stay clear of the overlay line (a body near the top of a
      // small view put its name on it).
      for (std::size_t i = labels_begin; i < labels_end; ++i)
        v.texts[i].position_px.y = std::max(v.texts[i].position_px.y, y + 1.5f * font_px_);
    }
  }
  if (run.diverged && k > last)
    v.texts.push_back({"diverged: stopped at t = " + std::to_string(clock_.time(last)).substr(0, 6) + " s",
                       {12.0f, top_px + 30.0f + 1.6f * font_px_}, font_px_, {0.75f, 0.1f, 0.1f, 1.0f}});
  return v;
}

viz::DrawList FrameBuilder::build(long k) const {
  viz::DrawList dl;
  const Eigen::Vector3d& bg = scene_.render.output.background;
  dl.background = rgba(bg, 1.0f);
  dl.columns = columns_;
  const viz::Color ink{0.12f, 0.13f, 0.16f, 1.0f};
  if (explain_ && explain_->title_card(dl, k)) return dl;  // the animation waits
  if (explain_ && !scene_.render.explain.views.empty()) {
    explain_->add_views(dl, k);
  } else {
    for (size_t r = 0; r < runs_.size(); ++r)
      dl.views.push_back(world_view(r, k, camera_, width_ / columns_, height_ / rows_));
  }
  if (scene_.render.draw.legend && scene_.render.draw.axes) {
    std::string legend = "principal axes:  red = smallest moment   green = intermediate   blue = largest";
    if (draw_.angular_momentum) legend += "   orange = L";
    if (draw_.omega) legend += "   purple = omega";
    dl.texts.push_back({legend, {12.0f, static_cast<float>(height_) - 26.0f}, 15.0f, ink});
  }
  if (explain_) explain_->add_text(dl, k);
  return dl;
}

}  // namespace tumble::run
