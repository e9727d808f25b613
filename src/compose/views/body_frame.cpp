// The `body_frame` view kind: one body seen from a camera fixed in its own
// axes (by default the scene camera's direction at t = 0), so the body stands
// still while L and ω turn around it. It shows its own body only (no other
// body crosses it). With `up` the camera is fixed in its principal axes
// instead (azimuth and elevation about e₃, as a momentum_sphere's). Where the
// camera turns with the body, L is drawn bold out to a faint sphere round the
// body, its path on it. The camera backs off until the body and its arrows
// stay inside the content rectangle in every frame.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "compose/camera_fit.hpp"
#include "compose/panel.hpp"
#include "compose/views/kinds.hpp"
#include "core/dynamics.hpp"
#include "viz/surfaces.hpp"
#include "viz/text_layout.hpp"

namespace tumble::compose {

namespace {

constexpr double kBodyMargin = 0.04;
constexpr long kBodyFitSamples = 240;
constexpr float kBodyAlpha = 0.6f;
constexpr double kSphere = 1.2;   // L's sphere, body radii: the box inside it
constexpr double kLBold = 1.6;    // L's shaft, times the other arrows'
const viz::Color kSphereFill{0.55f, 0.58f, 0.66f, 0.10f};
const viz::Color kSphereRim{0.35f, 0.37f, 0.45f, 0.45f};

// The camera at t = 0: aimed at the body from the view's azimuth and
// elevation (default: the scene camera's direction), `distance` body radii away.
viz::Camera body_camera(const scene::Scene& s, const viz::Camera& scene_cam, const scene::ViewCamera& c,
                        const RigidBodyModel& m, const BodyState& s0) {
  const glm::dvec3 d = glm::normalize(scene_cam.position - scene_cam.target);
  const double az = c.azimuth_deg ? glm::radians(*c.azimuth_deg) : std::atan2(d.y, d.x);
  const double el = c.elevation_deg ? glm::radians(*c.elevation_deg) : std::asin(std::clamp(d.z, -0.95, 0.95));
  viz::Camera cam;
  cam.fov_y_deg = s.render.camera.fov_y_deg;
  const double r = viz::box_radius(m);
  const double dist = c.distance.value_or(std::max(2.2, 1.15 / std::sin(glm::radians(cam.fov_y_deg) / 2))) * r;
  cam.target = viz::to_glm(s0.c);
  cam.position = cam.target + dist * glm::dvec3(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
  cam.up = {0, 0, 1};
  cam.near_m = 0.05 * dist;
  cam.far_m = 20 * dist;
  if (c.up) {  // fixed in principal axes, as a momentum_sphere's fixed camera: azimuth from e₁ about e₃, elevation above e₁e₂
    const double paz = glm::radians(c.azimuth_deg.value_or(0)), pel = glm::radians(c.elevation_deg.value_or(30));
    const Eigen::Vector3d dir(std::cos(pel) * std::cos(paz), std::cos(pel) * std::sin(paz), std::sin(pel));
    cam.position = cam.target + dist * viz::to_glm(s0.q * dir);
    cam.up = viz::to_glm(s0.q * Eigen::Vector3d((*c.up)[0], (*c.up)[1], (*c.up)[2]));
    return cam;
  }
  if (c.across != 0)  // across L at t = 0, L up: the camera then turns with the body
    return across_camera(s0.c, s0.L, c.across, c.azimuth_deg.value_or(s.render.camera.azimuth_deg),
                         c.elevation_deg.value_or(s.render.camera.elevation_deg), dist, cam.fov_y_deg);
  return cam;
}

class BodyFramePanel : public Panel {
 public:
  BodyFramePanel(const PanelContext& ctx, std::size_t index)
      : ctx_(ctx), vc_(ctx.scene.render.explain.views[index]), body_(view_body(ctx, index)) {}
  std::string name() const override { return "body_frame"; }
  std::vector<std::string> overlay(long k) const override { return ctx_.world.overlay(0, k); }
  int overlay_lines() const override { return ctx_.world.overlay_lines(0); }
  std::vector<viz::KeyEntry> key() const override {
    return ctx_.scene.render.explain.key ? bodies_key(ctx_, body_) : std::vector<viz::KeyEntry>{};
  }

  void fit(glm::vec2 size) override {
    size_ = size;
    const double aspect = size.x / std::max(size.y, 1.0f);
    const scene::Run& run = ctx_.runs[0];
    if (run.frames.empty()) return;
    camera_ = body_camera(ctx_.scene, scene_camera(ctx_.scene, ctx_.runs, aspect), vc_.camera,
                          ctx_.scene.bodies[body_].model, run.frames[0][body_]);
    std::vector<Shot> shots;
    Outlines outlines;
    const long n = static_cast<long>(run.frames.size());
    for (long i = 0; i < std::min(n, kBodyFitSamples); ++i) {
      const viz::View v = content(n <= kBodyFitSamples ? i : i * (n - 1) / (kBodyFitSamples - 1));
      shots.push_back(solid_shot(v, outlines));
      for (const viz::PolylineItem& l : v.polylines)  // L's trail stays in view too
        if (l.name == "L_trail") shots.back().points.insert(shots.back().points.end(), l.points.begin(), l.points.end());
    }
    // Arrows carry their names past (or, short of room, beside) their tips: a name's width across, half a line up and down.
    const double tip = viz::text_px(viz::TextRole::label, ctx_.frame_h, ctx_.text_scale());
    const Margins m{1.4 * tip / (0.5 * std::max(size.x, 1.0f)), 0.6 * tip / (0.5 * std::max(size.y, 1.0f))};
    camera_ = backed_off(camera_, backoff(shots, aspect, kBodyMargin, vc_.camera.distance ? 1.0 : 0.2, m));
  }

  viz::View content(long k) const override {
    const scene::Run& run = ctx_.runs[0];
    const long kk = last_frame(run, k);
    viz::Camera cam = camera_;
    if (kk >= 0) {
      // The camera keeps its offset (and, following, its up) in the body's own axes.
      const RigidBodyModel& m = ctx_.scene.bodies[body_].model;
      const BodyState& s0 = run.frames[0][body_];
      const BodyState& sk = run.frames[static_cast<std::size_t>(kk)][body_];
      const Eigen::Quaterniond turn = vc_.camera.follow.value_or(true)
                                          ? Eigen::Quaterniond(cloud_orientation(m, sk) * cloud_orientation(m, s0).conjugate())
                                          : Eigen::Quaterniond::Identity();
      const glm::dvec3 off = cam.position - cam.target;
      cam.target = viz::to_glm(sk.c);
      cam.position = cam.target + viz::to_glm(turn * Eigen::Vector3d(off.x, off.y, off.z));
      cam.up = viz::to_glm(turn * Eigen::Vector3d(cam.up.x, cam.up.y, cam.up.z));
    }
    viz::View v = ctx_.world.view(0, k, cam, int(size_.x), int(size_.y), body_);
    v.name = name();
    // The view's title names its body: no name label on a body that stands still in it.
    std::erase_if(v.texts, [](const viz::TextItem& t) { return t.name.rfind("label:", 0) == 0; });
    // A camera turning with the body: the body a little see-through, as it is
    // the frame here and the vectors turning inside it (L, ω, an axis along the
    // line of sight) stay seen and named.
    if (vc_.camera.follow.value_or(true))
      for (viz::SurfaceItem& sf : v.surfaces)
        if (sf.name.empty()) sf.color.a = std::min(sf.color.a, kBodyAlpha);
    // L's path as the body sees it, only where the camera turns with the body: from a camera fixed in
    // space L stands still, and a curve turning with the body beside it reads as a trail of nothing shown.
    if (kk >= 0 && vc_.camera.follow.value_or(true)) {
      on_sphere(v, cam, ctx_.runs[0].frames[static_cast<std::size_t>(kk)][body_].c);
      add_L_trail(v, kk);
    }
    return v;
  }

 private:
  // Seen from the body, L is a direction that wanders: drawn bold from the
  // centre out to a faint sphere round the body (radius kSphere body radii,
  // so the whole box is inside it), its path on that sphere's surface.
  void on_sphere(viz::View& v, const viz::Camera& cam, const Eigen::Vector3d& c) const {
    const auto L = std::find_if(v.arrows.begin(), v.arrows.end(), [](const viz::ArrowItem& a) { return a.name == "L"; });
    if (L == v.arrows.end() || glm::length(L->vector) <= 0) return;
    const double r = kSphere * viz::box_radius(ctx_.scene.bodies[body_].model);
    const glm::dvec3 centre = viz::to_glm(c);
    L->origin = centre;
    L->vector = r * glm::normalize(L->vector);
    L->radius *= kLBold;
    L->tip_rank = -1;  // named first: the other names make way for it
    v.surfaces.push_back(viz::ellipsoid(centre, glm::dmat3(1.0), glm::dvec3(r), kSphereFill));
    v.surfaces.back().name = "L_sphere";
    // Its outline: the circle where the lines of sight touch it.
    const glm::dvec3 to_eye = cam.position - centre;
    const double d = glm::length(to_eye);
    if (d <= r) return;
    const glm::dvec3 n = to_eye / d, a = glm::normalize(glm::cross(n, std::abs(n.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0)));
    const glm::dvec3 b = glm::cross(n, a);
    const double rho = r * std::sqrt(1 - r * r / (d * d));
    viz::PolylineItem rim{{}, kSphereRim, 1.5f, false, "L_sphere_rim"};
    for (int i = 0; i <= 96; ++i) {
      const double phi = 2 * std::numbers::pi * i / 96;
      rim.points.push_back(centre + (r * r / d) * n + rho * (std::cos(phi) * a + std::sin(phi) * b));
    }
    v.polylines.push_back(std::move(rim));
  }

  // The path of L's tip so far, as seen from the body: each earlier L turned
  // by the body's turn since then, so it rides with the body as the camera does.
  void add_L_trail(viz::View& v, long kk) const {
    const auto L = std::find_if(v.arrows.begin(), v.arrows.end(), [](const viz::ArrowItem& a) { return a.name == "L"; });
    if (L == v.arrows.end()) return;
    const scene::Run& run = ctx_.runs[0];
    const RigidBodyModel& m = ctx_.scene.bodies[body_].model;
    const BodyState& sk = run.frames[static_cast<std::size_t>(kk)][body_];
    const Eigen::Quaterniond now(cloud_orientation(m, sk));
    const glm::dvec3 tip = L->vector;
    viz::PolylineItem trail{{}, viz::color_of(viz::Meaning::L, 0.8f), 3.0f, false, "L_trail"};
    trail.over_glass = true;  // on the sphere's near side, in full colour
    for (long j = 0; j <= kk; ++j) {
      const BodyState& sj = run.frames[static_cast<std::size_t>(j)][body_];
      const Eigen::Quaterniond turn = now * Eigen::Quaterniond(cloud_orientation(m, sj)).conjugate();
      trail.points.push_back(L->origin + viz::to_glm(turn * Eigen::Vector3d(tip.x, tip.y, tip.z)));
    }
    if (trail.points.size() >= 2) v.polylines.push_back(std::move(trail));
  }

  const PanelContext& ctx_;
  const scene::ViewConfig& vc_;
  std::size_t body_;
  glm::vec2 size_{1, 1};
  viz::Camera camera_;
};

}  // namespace

std::unique_ptr<Panel> make_body_frame(const PanelContext& ctx, std::size_t index) {
  return std::make_unique<BodyFramePanel>(ctx, index);
}

}  // namespace tumble::compose
