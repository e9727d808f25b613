// The `poinsot` view kind: Poinsot's construction (viz/poinsot.hpp), the
// inertia ellipsoid rolling on the invariable plane, its camera backed off
// until the construction, its arrows and both curves of the whole video stay
// inside the content rectangle; its key beside it.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "compose/camera_fit.hpp"
#include "compose/panel.hpp"
#include "compose/view_layout.hpp"
#include "compose/views/kinds.hpp"
#include "core/dynamics.hpp"
#include "compose/world_views.hpp"
#include "viz/body_in_ellipsoid.hpp"
#include "viz/poinsot.hpp"

namespace tumble::compose {

namespace {

constexpr double kPoinsotMargin = 0.04;
constexpr long kPoinsotFitSamples = 120;
constexpr double kPoinsotClosest = 0.3;
constexpr double kCloseUpClosest = 0.02;  // a close-up of the contact region: up to 50 times nearer
constexpr float kBodyAlpha = 0.3f;  // the body inside its ellipsoid: seen, and L and ω from its centre clearly through it

// Points on the inertia ellipsoid's surface (its unit sphere under its model), for the camera fit.
void add_ellipsoid_points(const viz::SurfaceItem& sf, std::vector<glm::dvec3>& out) {
  constexpr int kLat = 8, kLon = 16;
  for (int i = 0; i <= kLat; ++i)
    for (int j = 0; j < kLon; ++j) {
      const double th = std::numbers::pi * i / kLat, ph = 2 * std::numbers::pi * j / kLon;
      const glm::dvec3 u(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
      out.push_back(glm::dvec3(sf.model * glm::dvec4(u, 1.0)));
    }
}

// A close-up keeps its camera where it stands and narrows its field: moved
// nearer, it would stand inside the ellipsoid. Near the target the picture
// scales as if the camera stood `factor` times as far.
viz::Camera zoomed(viz::Camera c, double factor) {
  c.fov_y_deg = 2 * glm::degrees(std::atan(factor * std::tan(0.5 * glm::radians(c.fov_y_deg))));
  return c;
}

// The narrowing (zoomed's factor) that keeps every point of `shots` inside
// the margins: a narrower field scales each point's NDC by 1/factor.
double narrowing(const std::vector<Shot>& shots, double aspect) {
  double factor = kCloseUpClosest;
  for (const Shot& s : shots) {
    const CameraMatrices m = camera_matrices(s.camera, static_cast<float>(aspect));
    for (const glm::dvec3& p : s.points) {
      const glm::dvec4 clip = glm::dmat4(m.proj) * glm::dmat4(m.view) * glm::dvec4(p, 1.0);
      if (clip.w <= 0) continue;
      factor = std::max({factor, std::abs(clip.x / clip.w) / (1 - kPoinsotMargin), std::abs(clip.y / clip.w) / (1 - kPoinsotMargin)});
    }
  }
  return std::min(factor, 1.0);
}

class PoinsotPanel : public Panel {
 public:
  PoinsotPanel(const PanelContext& ctx, std::size_t index)
      : ctx_(ctx), vc_(ctx.scene.render.explain.views[index]), body_(view_body(ctx, index)),
        look_(body_look(ctx.scene.bodies[body_], false)) {
    const auto& views = ctx.scene.render.explain.views;
    for (std::size_t j = 0; j < views.size(); ++j)
      if (j != index && views[j].kind == scene::ViewKind::poinsot && views[j].close_up && view_body(ctx, j) == body_)
        has_close_up_ = true;
  }
  std::string name() const override { return "poinsot"; }
  std::vector<viz::KeyEntry> key() const override {
    return ctx_.scene.render.explain.key ? viz::poinsot_key(vc_.separatrix) : std::vector<viz::KeyEntry>{};
  }

  void fit(glm::vec2 size) override {
    size_ = size;
    if (ctx_.runs.empty() || ctx_.runs[0].frames.empty()) return;
    const long n = static_cast<long>(ctx_.runs[0].frames.size());
    std::vector<Shot> shots;
    for (long i = 0; i < std::min(n, kPoinsotFitSamples); ++i) {
      const viz::View v = build(n <= kPoinsotFitSamples ? i : i * (n - 1) / (kPoinsotFitSamples - 1));
      viz::View arrows = v;
      arrows.surfaces.clear();  // the plane is cut at the content's edges; the ellipsoid is added below
      Shot s{v.camera, solid_points(arrows)};
      for (const viz::PolylineItem& l : v.polylines)
        if (!l.name.empty()) s.points.insert(s.points.end(), l.points.begin(), l.points.end());
      for (const viz::SurfaceItem& sf : v.surfaces)
        if (sf.name == "ellipsoid" && !vc_.close_up) add_ellipsoid_points(sf, s.points);
      shots.push_back(std::move(s));
    }
    // Closer too: the construction, not the plane (cut at the content's edges), fills the content;
    // close up, the curves and the contact point alone.
    const double aspect = size.x / std::max(size.y, 1.0f);
    backoff_ = vc_.close_up ? narrowing(shots, aspect) : backoff(shots, aspect, kPoinsotMargin, kPoinsotClosest);
  }

  viz::View content(long k) const override {
    if (ctx_.runs.empty()) return {};
    const long kk = last_frame(ctx_.runs[0], k);
    if (kk < 0) return {};
    viz::View v = build(kk);
    v.camera = vc_.close_up ? zoomed(v.camera, backoff_) : backed_off(v.camera, backoff_);
    return v;
  }

 private:
  viz::View build(long kk) const {
    const scene::Run& run = ctx_.runs[0];
    const RigidBodyModel& m = ctx_.scene.bodies[body_].model;
    const BodyState& s = run.frames[static_cast<std::size_t>(kk)][body_];
    viz::PoinsotInput in;
    in.q = s.q;
    in.inertia = m.inertia;
    in.L = s.L;
    for (std::size_t j = 0; j < run.path_end(kk); ++j) {  // with sub-frame samples: smooth curves
      in.omega_principal_history.push_back(omega_principal(m, run.path[j][body_]));
      in.omega_world_history.push_back(omega_world(m, run.path[j][body_]));
    }
    const scene::ViewCamera& c = vc_.camera;
    in.camera.azimuth_deg = c.azimuth_deg.value_or(in.camera.azimuth_deg);
    in.camera.elevation_deg = c.elevation_deg.value_or(in.camera.elevation_deg);
    in.camera.distance = c.distance.value_or(in.camera.distance);
    in.width_px = size_.x, in.height_px = size_.y;
    in.frame_h = ctx_.frame_h;
    in.text_scale = ctx_.text_scale();
    in.separatrix = vc_.separatrix;
    in.close_up = vc_.close_up;
    in.name_plane = !has_close_up_;
    in.dot_scale = vc_.close_up ? 1.5 * backoff_ : 1.0;  // the field narrowed by backoff_: the dots a little larger on screen than elsewhere, the eye's first stop
    viz::View v;
    viz::build_poinsot(v, in);
    // The body the ellipsoid belongs to, inside it, turning with it (not in a close-up of the contact).
    if (!vc_.close_up) viz::add_body_in_ellipsoid(v, look_, s.q, m.cloud_from_principal, m.com_cloud, m.inertia, kBodyAlpha);
    return v;
  }

  const PanelContext& ctx_;
  const scene::ViewConfig& vc_;
  std::size_t body_;
  viz::BodyLook look_;  // its surfaces, drawn inside the ellipsoid
  glm::vec2 size_{1, 1};
  double backoff_ = 1;
  bool has_close_up_ = false;  // another view shows this body's contact close up (and names the plane)
};

}  // namespace

std::unique_ptr<Panel> make_poinsot(const PanelContext& ctx, std::size_t index) {
  return std::make_unique<PoinsotPanel>(ctx, index);
}

}  // namespace tumble::compose
