#include "compose/explain_views.hpp"

#include <algorithm>
#include <cmath>

#include "core/dynamics.hpp"
#include "scene/frame_clock.hpp"
#include "viz/captions.hpp"
#include "viz/key.hpp"
#include "viz/palette.hpp"
#include "viz/momentum_sphere.hpp"
#include "viz/poinsot.hpp"
#include "viz/strip_chart.hpp"
#include "viz/text_layout.hpp"

namespace tumble::compose {

namespace {

glm::dvec3 to_glm(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

// How the plot shows each series of scene::plot_series_names(): its name in
// the key and its colour (viz/palette.hpp: principal components and angles
// take their axis' colour; the cloud-axis components, which are no principal
// axis, greys).
struct SeriesLook {
  const char* name;
  const char* shown;
  viz::Color color;
};
const std::vector<SeriesLook>& series_looks() {
  using viz::Meaning;
  static const std::vector<SeriesLook> looks = {
      {"w1", "\u03c9\u2081", viz::color_of(Meaning::axis1)},
      {"w2", "\u03c9\u2082", viz::color_of(Meaning::axis2)},
      {"w3", "\u03c9\u2083", viz::color_of(Meaning::axis3)},
      {"wbx", "\u03c9x (cloud axes)", {0.30f, 0.30f, 0.34f, 1}},
      {"wby", "\u03c9y (cloud axes)", {0.50f, 0.50f, 0.55f, 1}},
      {"wbz", "\u03c9z (cloud axes)", {0.68f, 0.68f, 0.72f, 1}},
      {"|w|", "|\u03c9|", viz::color_of(Meaning::omega)},
      {"energy_error", "\u0394E/E", viz::color_of(Meaning::ink)},
      {"axis1_L", "\u2220(e\u2081, L)", viz::color_of(Meaning::axis1)},
      {"axis2_L", "\u2220(e\u2082, L)", viz::color_of(Meaning::axis2)},
      {"axis3_L", "\u2220(e\u2083, L)", viz::color_of(Meaning::axis3)}};
  return looks;
}

const SeriesLook& series_look(const std::string& name) {
  for (const SeriesLook& l : series_looks())
    if (name == l.name) return l;
  return series_looks()[7];
}

}  // namespace

double series_value(const std::string& name, const RigidBodyModel& m, const BodyState& s, double e0) {
  if (name == "w1" || name == "w2" || name == "w3") return omega_principal(m, s)[name[1] - '1'];
  if (name == "wbx" || name == "wby" || name == "wbz") return omega_body(m, s)[name[2] - 'x'];
  if (name == "|w|") return omega_world(m, s).norm();
  if (name == "energy_error") return (total_energy(m, s) - e0) / std::max(std::abs(e0), 1e-300);
  if (name.size() == 7 && name.rfind("axis", 0) == 0) return principal_axis_angles_to_L(s)[name[4] - '1'];
  return 0;
}

namespace {

viz::SphereCameraSettings sphere_settings(const scene::ViewCamera& c, viz::SphereCameraSettings s) {
  s.azimuth_deg = c.azimuth_deg.value_or(s.azimuth_deg);
  s.elevation_deg = c.elevation_deg.value_or(s.elevation_deg);
  s.distance = c.distance.value_or(s.distance);
  s.follow = c.follow.value_or(s.follow);
  return s;
}

// The body_frame view's camera at t = 0: aimed at the body from `c`'s azimuth
// and elevation (default: the scene camera's direction), `distance` body radii away.
viz::Camera body_camera(const scene::Scene& s, const viz::Camera& scene_cam, const scene::ViewCamera& c,
                        const RigidBodyModel& m, const BodyState& s0) {
  const glm::dvec3 d = glm::normalize(scene_cam.position - scene_cam.target);
  const double az = c.azimuth_deg ? glm::radians(*c.azimuth_deg) : std::atan2(d.y, d.x);
  const double el = c.elevation_deg ? glm::radians(*c.elevation_deg) : std::asin(std::clamp(d.z, -0.95, 0.95));
  viz::Camera cam;
  cam.fov_y_deg = s.render.camera.fov_y_deg;
  const double r = viz::box_radius(m);
  const double dist = c.distance.value_or(std::max(2.2, 1.15 / std::sin(glm::radians(cam.fov_y_deg) / 2))) * r;
  cam.target = to_glm(s0.c);
  cam.position = cam.target + dist * glm::dvec3(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
  cam.up = {0, 0, 1};
  cam.near_m = 0.05 * dist;
  cam.far_m = 20 * dist;
  return cam;
}

}  // namespace

ExplainViews::ExplainViews(const WorldViews& world, const scene::Scene& s, const std::vector<scene::Run>& runs, int width,
                           int height)
    : world_(world), scene_(s), runs_(runs), width_(width), height_(height) {
  for (const scene::ViewConfig& vc : s.render.explain.views) {
    Slot slot;
    const std::array<double, 4> f = vc.viewport.value_or(std::array<double, 4>{0, 0, 1, 1});
    slot.width_px = std::max(1, static_cast<int>(std::lround(f[2] * width)));
    slot.height_px = std::max(1, static_cast<int>(std::lround(f[3] * height)));
    if (const scene::Body* b = s.find_body(vc.body)) slot.body = static_cast<std::size_t>(b - s.bodies.data());
    slot.camera = scene_camera(s, runs, static_cast<double>(slot.width_px) / slot.height_px);
    const RigidBodyModel& m = s.bodies[slot.body].model;
    if (vc.kind == scene::ViewKind::body_frame && !runs.empty() && !runs[0].frames.empty())
      slot.camera = body_camera(s, slot.camera, vc.camera, m, runs[0].frames[0][slot.body]);
    if (vc.kind == scene::ViewKind::momentum_sphere) {
      slot.sphere = sphere_settings(vc.camera, viz::SphereCameraSettings{});
      if (!runs.empty()) {
        // Followed from t = 0 through every path sample: frame k alone gets the pose of a full run.
        std::vector<Eigen::Vector3d> pi;
        for (const auto& states : runs[0].path) pi.push_back(momentum_body(states[slot.body]));
        slot.track = viz::follow_track(runs[0].path_t, pi, slot.sphere);
      }
    }
    if (vc.kind == scene::ViewKind::poinsot) slot.sphere = sphere_settings(vc.camera, viz::PoinsotInput{}.camera);
    if (vc.kind == scene::ViewKind::plot && !runs.empty()) {
      // The value axis covers the whole run, so every frame shares it.
      double lo = 1e300, hi = -1e300;
      const scene::Run& run = runs[0];
      for (const auto& states : run.frames)
        for (const std::string& name : vc.series) {
          const double v = series_value(name, m, states[slot.body], run.energy0[slot.body]);
          if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
        }
      if (!(hi >= lo)) lo = -1, hi = 1;
      const double pad = 0.08 * std::max(hi - lo, 1e-12 + 1e-9 * std::abs(hi));
      slot.lo = lo - pad, slot.hi = hi + pad;
    }
    slots_.push_back(std::move(slot));
  }
  place_keys();
}

viz::View ExplainViews::bodies_view(std::size_t i, long k, bool key) const {
  const scene::ViewConfig& vc = scene_.render.explain.views[i];
  const Slot& slot = slots_[i];
  const scene::Run& run = runs_[0];
  const long kk = std::min(k, static_cast<long>(run.frames.size()) - 1);
  viz::Camera cam = slot.camera;
  const bool turn_with_body = vc.camera.follow.value_or(true);
  if (vc.kind == scene::ViewKind::body_frame && kk >= 0) {
    // The camera keeps its offset (and, following, its up) in the body's own
    // axes: the body stands still while L and the world turn around it.
    const RigidBodyModel& m = scene_.bodies[slot.body].model;
    const BodyState& s0 = run.frames[0][slot.body];
    const BodyState& sk = run.frames[static_cast<std::size_t>(kk)][slot.body];
    const Eigen::Quaterniond turn = turn_with_body ? Eigen::Quaterniond(cloud_orientation(m, sk) * cloud_orientation(m, s0).conjugate())
                                                   : Eigen::Quaterniond::Identity();
    const glm::dvec3 off = cam.position - cam.target;
    cam.target = to_glm(sk.c);
    cam.position = cam.target + to_glm(turn * Eigen::Vector3d(off.x, off.y, off.z));
    cam.up = to_glm(turn * Eigen::Vector3d(cam.up.x, cam.up.y, cam.up.z));
  }
  if (key && slot.key && slot.key->shift_px != 0) {  // the bodies move aside for their key
    viz::View panned;
    panned.camera = cam;
    viz::shift_content(panned, slot.key->shift_px, static_cast<float>(slot.height_px));
    cam = panned.camera;
  }
  viz::View head;
  const float w = static_cast<float>(slot.width_px);
  const float top = viz::add_view_title(head, vc.title, w, height_);
  viz::View v = world_.view(0, k, cam, slot.width_px, slot.height_px, top);
  v.name = vc.kind == scene::ViewKind::world ? "world" : "body_frame";
  for (viz::TextItem& t : head.texts) v.texts.push_back(std::move(t));
  if (key && slot.key) viz::add_key(v, key_entries(i), slot.key->top_left, viz::text_px(viz::TextRole::key, height_));
  return v;
}

namespace {

// What the momentum sphere and Poinsot's construction take alike from their
// slot: title, camera settings, key and its place, viewport and frame height.
template <class Input, class Slot>
void take_slot(Input& in, const Slot& slot, const std::string& title, bool key, int frame_h) {
  in.title = title;
  in.camera = slot.sphere;
  in.key = key && slot.key;
  in.key_spot = slot.key;
  in.width_px = static_cast<float>(slot.width_px), in.height_px = static_cast<float>(slot.height_px);
  in.frame_h = frame_h;
}

}  // namespace

viz::View ExplainViews::sphere_view(std::size_t i, long kk, bool layout) const {
  const scene::ViewConfig& vc = scene_.render.explain.views[i];
  const Slot& slot = slots_[i];
  const scene::Run& run = runs_[0];
  const RigidBodyModel& m = scene_.bodies[slot.body].model;
  viz::MomentumSphereInput in;
  in.inertia = m.inertia;
  in.momentum = momentum_body(run.frames[static_cast<std::size_t>(kk)][slot.body]);
  for (std::size_t j = 0; j < run.path_end(kk); ++j) in.history.push_back(momentum_body(run.path[j][slot.body]));
  in.two_E = in.momentum.dot(m.inv_inertia.cwiseProduct(in.momentum));
  if (!slot.track.empty()) in.pose = slot.track[std::min(run.path_end(kk), slot.track.size()) - 1];
  take_slot(in, slot, vc.title, !layout, height_);
  in.outline_only = layout;
  viz::View v;
  viz::build_momentum_sphere(v, in);
  return v;
}

viz::View ExplainViews::plot_view(std::size_t i, long k) const {
  const scene::ViewConfig& vc = scene_.render.explain.views[i];
  const Slot& slot = slots_[i];
  const scene::Run& run = runs_[0];
  const long kk = std::min(k, static_cast<long>(run.frames.size()) - 1);
  const RigidBodyModel& m = scene_.bodies[slot.body].model;
  viz::StripChartInput in;
  in.t0 = 0, in.t1 = scene_.simulation.duration, in.lo = slot.lo, in.hi = slot.hi;
  in.playhead = world_.clock().time(k);
  in.title = vc.title;
  for (const scene::SlowMotion& sm : scene_.render.explain.slow_motion)
    in.shaded.push_back({sm.start, sm.end, scene::speed_text(sm.time_scale)});
  in.frame_h = height_;
  for (long j = 0; j <= kk; ++j) in.times.push_back(world_.clock().time(j));
  for (const std::string& name : vc.series) {
    const SeriesLook& look = series_look(name);
    viz::Series series{look.shown, {}, look.color};
    for (long j = 0; j <= kk; ++j)
      series.values.push_back(series_value(name, m, run.frames[static_cast<std::size_t>(j)][slot.body], run.energy0[slot.body]));
    in.series.push_back(std::move(series));
  }
  viz::View v;
  viz::build_strip_chart(v, in, slot.width_px, slot.height_px, viz::text_px(viz::TextRole::tick, height_));
  return v;
}

viz::View ExplainViews::poinsot_view(std::size_t i, long kk, bool key) const {
  const scene::ViewConfig& vc = scene_.render.explain.views[i];
  const Slot& slot = slots_[i];
  const scene::Run& run = runs_[0];
  const RigidBodyModel& m = scene_.bodies[slot.body].model;
  const BodyState& s = run.frames[static_cast<std::size_t>(kk)][slot.body];
  viz::PoinsotInput in;
  in.q = s.q;
  in.inertia = m.inertia;
  in.L = s.L;
  for (std::size_t j = 0; j < run.path_end(kk); ++j) {  // with sub-frame samples: smooth curves
    in.omega_principal_history.push_back(omega_principal(m, run.path[j][slot.body]));
    in.omega_world_history.push_back(omega_world(m, run.path[j][slot.body]));
  }
  take_slot(in, slot, vc.title, key, height_);
  viz::View v;
  viz::build_poinsot(v, in);
  return v;
}

viz::View ExplainViews::view_at(std::size_t i, long k, bool layout) const {
  const scene::ViewConfig& vc = scene_.render.explain.views[i];
  const Slot& slot = slots_[i];
  const long kk = std::min(k, static_cast<long>(runs_[0].frames.size()) - 1);
  viz::View v;
  switch (vc.kind) {
    case scene::ViewKind::world:
    case scene::ViewKind::body_frame: v = bodies_view(i, k, !layout); break;
    case scene::ViewKind::momentum_sphere:
      if (kk >= 0) v = sphere_view(i, kk, layout);
      break;
    case scene::ViewKind::plot: v = plot_view(i, k); break;
    case scene::ViewKind::poinsot:
      if (kk >= 0) v = poinsot_view(i, kk, !layout);
      break;
  }
  // Labels are in no key's way (keep_clear passes over them): a layout leaves them unsettled.
  if (!layout)
    viz::settle_labels(v, static_cast<float>(slot.width_px), static_cast<float>(slot.height_px), frame_text_boxes(i, k));
  if (vc.viewport) v.viewport = glm::dvec4((*vc.viewport)[0], (*vc.viewport)[1], (*vc.viewport)[2], (*vc.viewport)[3]);
  else v.viewport = glm::dvec4(0, 0, 1, 1);
  return v;
}

void ExplainViews::add_views(viz::DrawList& dl, long k) const {
  for (std::size_t i = 0; i < slots_.size(); ++i) dl.views.push_back(view_at(i, k));
}

void ExplainViews::add_text(viz::DrawList& dl, long k) const {
  const scene::ExplainConfig& e = scene_.render.explain;
  const scene::FrameClock& clock = world_.clock();
  const double tau = static_cast<double>(k) / clock.fps();  // video time
  const double rate = clock.rate(k);
  const auto badge = viz::speed_badge(scene::speed_text(rate), rate < 1, width_, height_);
  // The captions keep clear of the badge's corner.
  const float side = badge ? static_cast<float>(width_) - badge->position_px.x : 0.0f;
  for (const scene::Caption& c : e.captions) {
    const float a = viz::fade_alpha(tau, clock.video_time(c.start), clock.video_time(c.end));
    if (a > 0)
      for (viz::TextItem& t : viz::caption_items(c.text, a, width_, height_, side)) dl.texts.push_back(std::move(t));
  }
  if (badge) dl.texts.push_back(*badge);
  if (!frame_key_.empty()) {
    viz::View key;
    viz::add_key(key, frame_key_, frame_key_at_, viz::text_px(viz::TextRole::key, height_));
    for (viz::TextItem& t : key.texts) dl.texts.push_back(std::move(t));
  }
  dl.notes = notes_;
}

bool ExplainViews::title_card(viz::DrawList& dl, long k) const {
  const scene::TitleCard& t = scene_.render.explain.title;
  if (t.hold <= 0 || !world_.clock().on_title_card(k)) return false;
  const double tau = static_cast<double>(k) / world_.clock().fps();
  dl.background = viz::kTitleCardBackground;
  dl.views.clear();
  for (viz::TextItem& item : viz::title_items(t.text, t.subtitle, viz::fade_alpha(tau, -1.0, t.hold), width_, height_))
    dl.texts.push_back(std::move(item));
  return true;
}

}  // namespace tumble::compose
