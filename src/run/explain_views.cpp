#include "run/explain_views.hpp"

#include <algorithm>
#include <cmath>

#include "core/dynamics.hpp"
#include "viz/captions.hpp"
#include "viz/momentum_sphere.hpp"
#include "viz/poinsot.hpp"
#include "viz/strip_chart.hpp"

namespace tumble::run {

namespace {

glm::dvec3 to_glm(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

const viz::Color kSeriesColors[] = {{0.86f, 0.15f, 0.15f, 1}, {0.12f, 0.62f, 0.20f, 1}, {0.15f, 0.30f, 0.90f, 1},
                                    {0.10f, 0.10f, 0.14f, 1}, {0.60f, 0.20f, 0.75f, 1}, {0.95f, 0.55f, 0.05f, 1}};

// ω_body components take the colours of the axes they are closest to in name.
viz::Color series_color(const std::string& name, std::size_t i) {
  if (name == "wbx" || name == "axis1_L") return kSeriesColors[0];
  if (name == "wby" || name == "axis2_L") return kSeriesColors[1];
  if (name == "wbz" || name == "axis3_L") return kSeriesColors[2];
  return kSeriesColors[3 + i % 3];
}

}  // namespace

double series_value(const std::string& name, const RigidBodyModel& m, const BodyState& s, double e0) {
  if (name == "wbx" || name == "wby" || name == "wbz") return omega_body(m, s)[name[2] - 'x'];
  if (name == "|w|") return omega_world(m, s).norm();
  if (name == "energy_error") return (total_energy(m, s) - e0) / std::max(std::abs(e0), 1e-300);
  if (name.size() == 7 && name.rfind("axis", 0) == 0) return principal_axis_angles_to_L(s)[name[4] - '1'];
  return 0;
}

ExplainViews::ExplainViews(const FrameBuilder& fb, const scene::Scene& s, const std::vector<Run>& runs, int width,
                           int height)
    : fb_(fb), scene_(s), runs_(runs), width_(width), height_(height) {
  for (const scene::ViewConfig& vc : s.render.explain.views) {
    Slot slot;
    const std::array<double, 4> f = vc.viewport.value_or(std::array<double, 4>{0, 0, 1, 1});
    slot.width_px = std::max(1, static_cast<int>(std::lround(f[2] * width)));
    slot.height_px = std::max(1, static_cast<int>(std::lround(f[3] * height)));
    if (const scene::Body* b = s.find_body(vc.body)) slot.body = static_cast<std::size_t>(b - s.bodies.data());
    slot.camera = scene_camera(s, runs, static_cast<double>(slot.width_px) / slot.height_px);
    if (vc.kind == scene::ViewKind::plot && !runs.empty()) {
      // The value axis covers the whole run, so every frame shares it.
      double lo = 1e300, hi = -1e300;
      const Run& run = runs[0];
      for (const auto& states : run.frames)
        for (const std::string& name : vc.series) {
          const double v = series_value(name, s.bodies[slot.body].model, states[slot.body], run.energy0[slot.body]);
          if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
        }
      if (!(hi >= lo)) lo = -1, hi = 1;
      const double pad = 0.08 * std::max(hi - lo, 1e-12 + 1e-9 * std::abs(hi));
      slot.lo = lo - pad, slot.hi = hi + pad;
    }
    slots_.push_back(slot);
  }
}

viz::View ExplainViews::view_at(std::size_t i, long k) const {
  const scene::ViewConfig& vc = scene_.render.explain.views[i];
  const Slot& slot = slots_[i];
  const Run& run = runs_[0];
  const long last = static_cast<long>(run.frames.size()) - 1;
  const long kk = std::min(k, last);
  const RigidBodyModel& m = scene_.bodies[slot.body].model;
  auto state = [&](long j) -> const BodyState& { return run.frames[static_cast<std::size_t>(j)][slot.body]; };
  // A titled world view's text starts below the title, which the renderer draws top-left.
  const float title_px = vc.title.empty() ? 0.0f : viz::view_label_metrics(static_cast<float>(slot.height_px)).bottom_px;
  viz::View v;
  switch (vc.kind) {
    case scene::ViewKind::world: v = fb_.world_view(0, k, slot.camera, slot.width_px, slot.height_px, title_px); break;
    case scene::ViewKind::body_frame: {
      // The camera keeps its offset and up in the body's own axes: the body
      // stands still while L and the world turn around it.
      viz::Camera cam = slot.camera;
      if (kk >= 0) {
        const Eigen::Quaterniond r0 = cloud_orientation(m, state(0)), rk = cloud_orientation(m, state(kk));
        const Eigen::Quaterniond turn = rk * r0.conjugate();
        const glm::dvec3 off = cam.position - cam.target;
        const Eigen::Vector3d off_k = turn * Eigen::Vector3d(off.x, off.y, off.z);
        const Eigen::Vector3d up_k = turn * Eigen::Vector3d(cam.up.x, cam.up.y, cam.up.z);
        cam.target = to_glm(state(kk).c);
        cam.position = cam.target + to_glm(off_k);
        cam.up = to_glm(up_k);
      }
      v = fb_.world_view(0, k, cam, slot.width_px, slot.height_px, title_px);
      break;
    }
    case scene::ViewKind::momentum_sphere: {
      if (kk < 0) break;
      viz::MomentumSphereInput in;
      in.inertia = m.inertia;
      in.momentum = momentum_body(state(kk));
      for (std::size_t j = 0; j < run.path_end(kk); ++j) in.history.push_back(momentum_body(run.path[j][slot.body]));
      in.two_E = in.momentum.dot(m.inv_inertia.cwiseProduct(in.momentum));
      in.title = vc.title;
      viz::build_momentum_sphere(v, in, fb_.font_px());
      break;
    }
    case scene::ViewKind::plot: {
      viz::StripChartInput in;
      in.t0 = 0, in.t1 = scene_.simulation.duration, in.lo = slot.lo, in.hi = slot.hi;
      in.playhead = fb_.clock().time(k);
      in.title = vc.title;
      for (long j = 0; j <= kk; ++j) in.times.push_back(fb_.clock().time(j));
      for (std::size_t s = 0; s < vc.series.size(); ++s) {
        viz::Series series{vc.series[s], {}, series_color(vc.series[s], s)};
        for (long j = 0; j <= kk; ++j) series.values.push_back(series_value(vc.series[s], m, state(j), run.energy0[slot.body]));
        in.series.push_back(std::move(series));
      }
      viz::build_strip_chart(v, in, slot.width_px, slot.height_px, fb_.font_px());
      break;
    }
    case scene::ViewKind::poinsot: {
      if (kk < 0) break;
      viz::PoinsotInput in;
      in.q = state(kk).q;
      in.inertia = m.inertia;
      in.L = state(kk).L;
      for (std::size_t j = 0; j < run.path_end(kk); ++j) {  // with sub-frame samples: smooth curves
        in.omega_principal_history.push_back(omega_principal(m, run.path[j][slot.body]));
        in.omega_world_history.push_back(omega_world(m, run.path[j][slot.body]));
      }
      in.title = vc.title;
      viz::build_poinsot(v, in, fb_.font_px());
      break;
    }
  }
  if (vc.viewport) v.viewport = glm::dvec4((*vc.viewport)[0], (*vc.viewport)[1], (*vc.viewport)[2], (*vc.viewport)[3]);
  else v.viewport = glm::dvec4(0, 0, 1, 1);
  if (!vc.title.empty() && (vc.kind == scene::ViewKind::world || vc.kind == scene::ViewKind::body_frame))
    v.label = vc.title;
  return v;
}

void ExplainViews::add_views(viz::DrawList& dl, long k) const {
  for (std::size_t i = 0; i < slots_.size(); ++i) dl.views.push_back(view_at(i, k));
}

void ExplainViews::add_text(viz::DrawList& dl, long k) const {
  const scene::ExplainConfig& e = scene_.render.explain;
  const double tau = static_cast<double>(k) / fb_.clock().fps();  // video time
  for (const scene::Caption& c : e.captions) {
    const float a = viz::fade_alpha(tau, fb_.clock().video_time(c.start), fb_.clock().video_time(c.end));
    if (a > 0) dl.texts.push_back(viz::caption_item(c.text, a, width_, height_));
  }
  if (e.title.duration > 0) {
    const float a = viz::fade_alpha(tau, -1.0, e.title.duration);
    if (a > 0)
      for (viz::TextItem& t : viz::title_items(e.title.text, e.title.subtitle, a, width_, height_))
        dl.texts.push_back(std::move(t));
  }
}

}  // namespace tumble::run
