// The `momentum_sphere` view kind: Π = Rᵀ L on the sphere |Π| = |L| with the
// polhodes and the separatrix (viz/momentum_sphere.hpp), its camera following
// Π from t = 0 (or fixed) and its field of view showing the sphere, its axes
// and their labels whole in the content rectangle; its key beside it.
#include <algorithm>

#include "compose/panel.hpp"
#include "compose/views/kinds.hpp"
#include "core/dynamics.hpp"
#include "viz/momentum_sphere.hpp"
#include "viz/sphere_camera.hpp"

namespace tumble::compose {

namespace {

// What the content must show whole: the axes (1.35 |L|), their labels (at 1.47) and a margin.
constexpr double kFitRadius = 1.62;

viz::SphereCameraSettings sphere_settings(const scene::ViewCamera& c, viz::SphereCameraSettings s) {
  s.azimuth_deg = c.azimuth_deg.value_or(s.azimuth_deg);
  s.elevation_deg = c.elevation_deg.value_or(s.elevation_deg);
  s.distance = c.distance.value_or(s.distance);
  s.follow = c.follow.value_or(s.follow);
  return s;
}

class SpherePanel : public Panel {
 public:
  SpherePanel(const PanelContext& ctx, std::size_t index)
      : ctx_(ctx), body_(view_body(ctx, index)),
        settings_(sphere_settings(ctx.scene.render.explain.views[index].camera, viz::SphereCameraSettings{})) {
    if (ctx.runs.empty()) return;
    // Followed from t = 0 through every path sample: frame k alone gets the pose of a full run.
    std::vector<Eigen::Vector3d> pi;
    for (const auto& states : ctx.runs[0].path) pi.push_back(momentum_body(states[body_]));
    track_ = viz::follow_track(ctx.runs[0].path_t, pi, settings_);
  }
  std::string name() const override { return "momentum_sphere"; }
  std::vector<viz::KeyEntry> key() const override {
    if (!ctx_.scene.render.explain.key) return {};
    viz::MomentumSphereInput in = input(0);  // what it draws: Π and its energy at t = 0 (conserved)
    return viz::sphere_key(in);
  }
  void fit(glm::vec2 size) override { size_ = size; }

  viz::View content(long k) const override {
    viz::View v;
    const long kk = ctx_.runs.empty() ? -1 : last_frame(ctx_.runs[0], k);
    if (kk < 0) return v;
    viz::MomentumSphereInput in = input(kk);
    const scene::Run& run = ctx_.runs[0];
    for (std::size_t j = 0; j < run.path_end(kk); ++j) in.history.push_back(momentum_body(run.path[j][body_]));
    if (!track_.empty()) in.pose = track_[std::min(run.path_end(kk), track_.size()) - 1];
    viz::build_momentum_sphere(v, in);
    return v;
  }

 private:
  viz::MomentumSphereInput input(long kk) const {
    const RigidBodyModel& m = ctx_.scene.bodies[body_].model;
    viz::MomentumSphereInput in;
    in.inertia = m.inertia;
    if (!ctx_.runs.empty() && !ctx_.runs[0].frames.empty()) {
      in.momentum = momentum_body(ctx_.runs[0].frames[static_cast<std::size_t>(kk)][body_]);
      in.two_E = in.momentum.dot(m.inv_inertia.cwiseProduct(in.momentum));
    }
    in.camera = settings_;
    in.key = false;  // the layout draws it, beside the content
    in.width_px = size_.x, in.height_px = size_.y;
    in.frame_h = ctx_.frame_h;
    in.fit_radius = kFitRadius;
    return in;
  }

  const PanelContext& ctx_;
  std::size_t body_;
  viz::SphereCameraSettings settings_;
  std::vector<viz::SpherePose> track_;  // the camera at each path sample
  glm::vec2 size_{1, 1};
};

}  // namespace

std::unique_ptr<Panel> make_momentum_sphere(const PanelContext& ctx, std::size_t index) {
  return std::make_unique<SpherePanel>(ctx, index);
}

}  // namespace tumble::compose
