// The `momentum_sphere` view kind: Π = Rᵀ L on the sphere |Π| = |L| with the
// polhodes and the separatrix (viz/momentum_sphere.hpp), its camera following
// Π from t = 0 (or fixed) and its field of view showing the sphere, its axes
// and their labels whole in the content rectangle; its key beside it.
#include <algorithm>

#include "compose/panel.hpp"
#include "compose/views/kinds.hpp"
#include "core/dynamics.hpp"
#include "scene/frame_clock.hpp"
#include "viz/momentum_sphere.hpp"
#include "viz/palette.hpp"
#include "viz/sphere_camera.hpp"

namespace tumble::compose {

namespace {

// What the content must show whole: the axes (1.22 |L|), their labels past them and a margin (the ball 70 % of it).
constexpr double kFitRadius = 1.42;
constexpr double kPiTailSeconds = 0.4;  // simulated s of Π's path drawn behind the dot: the whole path is the polhode

viz::SphereCameraSettings sphere_settings(const scene::ViewCamera& c, viz::SphereCameraSettings s) {
  s.azimuth_deg = c.azimuth_deg.value_or(s.azimuth_deg);
  s.elevation_deg = c.elevation_deg.value_or(s.elevation_deg);
  s.distance = c.distance.value_or(s.distance);
  s.follow = c.follow.value_or(s.follow);
  if (c.up) s.up = Eigen::Vector3d((*c.up)[0], (*c.up)[1], (*c.up)[2]);
  return s;
}

// The view's camera: a lesson's default is the fixed textbook figure of the
// body's start (viz::textbook_camera); azimuth/elevation fix another
// direction; follow = true follows Π.
viz::SphereCameraSettings view_camera(const scene::ViewCamera& c, const Eigen::Vector3d& inertia, const Eigen::Vector3d& pi0) {
  const bool textbook = !c.follow.value_or(false) && !c.azimuth_deg && !c.elevation_deg;
  viz::SphereCameraSettings base;
  if (textbook) base = viz::textbook_camera(inertia, pi0);
  else base.follow = c.follow.value_or(false);
  base.reach = viz::kSphereReach;
  return sphere_settings(c, base);
}

// A track's name in the sphere's key, short (the key stands beside the ball):
// "exact Π", "Euler's Π" (the last word of the run's name, less a bracket).
std::string track_name(const scene::Run& run) {
  if (run.label == "exact") return "exact \u03a0";
  std::string t = short_title(run);
  t = t.substr(0, t.find(" ("));
  return t.substr(t.rfind(' ') + 1) + "'s \u03a0";
}

class SpherePanel : public Panel {
 public:
  SpherePanel(const PanelContext& ctx, std::size_t index)
      : ctx_(ctx), body_(view_body(ctx, index)), index_(index) {
    const scene::ViewCamera& c = ctx.scene.render.explain.views[index].camera;
    const Eigen::Vector3d pi0 = ctx.runs.empty() || ctx.runs[0].frames.empty()
                                    ? Eigen::Vector3d::UnitY()
                                    : Eigen::Vector3d(momentum_body(ctx.runs[0].frames[0][body_]));
    settings_ = view_camera(c, ctx.scene.bodies[body_].model.inertia, pi0);
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
    in.tracks = tracks(0);
    in.ellipsoid_alpha = static_cast<float>(ctx_.scene.render.explain.views[index_].ellipsoid_opacity.value_or(viz::kEnergyEllipsoidAlpha));
    return viz::sphere_key(in);
  }
  void fit(glm::vec2 size) override { size_ = size; }

  viz::View content(long k) const override {
    viz::View v;
    const long kk = ctx_.runs.empty() ? -1 : last_frame(ctx_.runs[0], k);
    if (kk < 0) return v;
    viz::MomentumSphereInput in = input(kk);
    const scene::Run& run = ctx_.runs[0];
    const double now = run.path_t[run.path_end(kk) - 1];
    const double since = in.trail ? -1e300 : now - kPiTailSeconds;  // a trail: from t = 0
    for (std::size_t j = 0; j < run.path_end(kk); ++j)
      if (run.path_t[j] >= since) in.history.push_back(momentum_body(run.path[j][body_]));
    if (!track_.empty()) in.pose = track_[std::min(run.path_end(kk), track_.size()) - 1];
    in.tracks = tracks(k);
    turn(k, in.camera);
    in.ellipsoid_alpha = static_cast<float>(ctx_.scene.render.explain.views[index_].ellipsoid_opacity.value_or(viz::kEnergyEllipsoidAlpha)) * fade_in(k);
    build_up(k, in);
    viz::build_momentum_sphere(v, in);
    return v;
  }

 private:
  // A fixed camera turning (the view's `turn`): eased from where it stands to
  // the turn's direction over its video seconds, from the first frame showing `at`.
  void turn(long k, viz::SphereCameraSettings& c) const {
    const auto& t = ctx_.scene.render.explain.views[index_].turn;
    if (!t || c.follow) return;
    const scene::FrameClock& clock = ctx_.world.clock();
    const double u = std::clamp((static_cast<double>(k) / clock.fps() - clock.video_time(t->at)) / t->seconds, 0.0, 1.0);
    const double s = u * u * (3 - 2 * u);  // smoothstep: no jerk at either end
    c.azimuth_deg += s * (t->azimuth_deg - c.azimuth_deg);
    c.elevation_deg += s * (t->elevation_deg - c.elevation_deg);
  }

  // The view's `build_up`: the figure drawn step by step from the first frame
  // showing its `at`; the ellipsoid shown for it, whether the view keeps it or not.
  void build_up(long k, viz::MomentumSphereInput& in) const {
    const auto& b = ctx_.scene.render.explain.views[index_].build_up;
    if (!b) return;
    const scene::FrameClock& clock = ctx_.world.clock();
    in.reveal = viz::sphere_reveal(static_cast<double>(k) / clock.fps() - clock.video_time(b->at), b->seconds, in.energy_ellipsoid);
    if (!in.reveal.ellipsoid) return;
    in.ellipsoid_alpha = static_cast<float>(ctx_.scene.render.explain.views[index_].ellipsoid_opacity.value_or(viz::kEnergyEllipsoidAlpha)) * *in.reveal.ellipsoid;
    in.energy_ellipsoid = true;
  }

  // The energy ellipsoid (the view's `ellipsoid_from`): faded in over a second of
  // video from the first frame showing that simulated time, so the eye sees it come;
  // its opacity the view's `ellipsoid_opacity` (a lesson's thin caps need more than the veil).
  float fade_in(long k) const {
    const double from = ctx_.scene.render.explain.views[index_].ellipsoid_from;
    if (from <= 0) return 1;
    const scene::FrameClock& clock = ctx_.world.clock();
    return static_cast<float>(std::clamp(static_cast<double>(k) / clock.fps() - clock.video_time(from), 0.0, 1.0));
  }

  // In a comparison, each run's Π from t = 0 on the one sphere: the exact
  // solution first, wide and grey (the cells' ghost colour), each method over it
  // in its own colour, narrower, so a method that keeps to it shows on it.
  std::vector<viz::SphereTrack> tracks(long k) const {
    std::vector<viz::SphereTrack> out;
    if (!ctx_.scene.render.explain.views[index_].paths_of.empty()) return body_tracks(k);
    if (ctx_.runs.size() < 2) return out;
    for (int exact : {1, 0})
      for (const scene::Run& run : ctx_.runs) {
        if ((run.label == "exact") != bool(exact)) continue;
        viz::SphereTrack t;
        t.name = track_name(run);
        t.color = exact ? kExactPathColor : run_color(run);
        t.width = exact ? 1.6f : 0.45f;  // thin: Euler's loops round −e₁ stay apart
        t.reported = bool(exact);  // the methods' paths and dots, over the exact one's, may lie under the axes' names
        const long kk = last_frame(run, k);
        if (kk >= 0 && !run.path.empty())
          for (std::size_t j = 0; j < run.path_end(kk); ++j) t.path.push_back(momentum_body(run.path[j][body_]));
        else if (kk >= 0)
          for (long j = 0; j <= kk; ++j) t.path.push_back(momentum_body(run.frames[static_cast<std::size_t>(j)][body_]));
        out.push_back(std::move(t));
      }
    return out;
  }

  // The view's `paths_of`: each body's Π from t = 0, times |L|/|L_b| (this view's
  // body's |L| over its own), so bodies of one inertia spun differently lie on the
  // one sphere; their energies' curves differ only by E/|L|², which the scaling keeps.
  std::vector<viz::SphereTrack> body_tracks(long k) const {
    // Bodies of one colour: all in the polhode's crimson, as each body's own sphere draws its
    // path, each told by where it runs (one key entry). Bodies of different colours: each path
    // and dot in its body's colour, as the key names it, so a dot is matched to its body at a glance.
    std::vector<viz::SphereTrack> out;
    const long kk = ctx_.runs.empty() ? -1 : last_frame(ctx_.runs[0], k);
    if (kk < 0 || ctx_.runs[0].frames.empty()) return out;
    const scene::Run& run = ctx_.runs[0];
    const double L = momentum_body(run.frames[0][body_]).norm();
    const auto& names = ctx_.scene.render.explain.views[index_].paths_of;
    std::vector<std::size_t> bodies;
    for (const std::string& n : names) bodies.push_back(static_cast<std::size_t>(ctx_.scene.find_body(n) - ctx_.scene.bodies.data()));
    bool distinct = true;
    for (std::size_t i = 0; i < bodies.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if ((ctx_.scene.bodies[bodies[i]].color - ctx_.scene.bodies[bodies[j]].color).norm() < 0.05) distinct = false;
    for (const std::size_t b : bodies) {
      const double Lb = momentum_body(run.frames[0][b]).norm();
      viz::SphereTrack t;
      t.name = ctx_.scene.bodies[b].label;
      if (distinct) {
        t.color = body_key_color(ctx_.scene.bodies[b]);
        t.key = "\u03a0: " + t.name;
      } else {
        t.color = viz::color_of(viz::Meaning::polhode);
        t.key = "polhode: each body's \u03a0";
      }
      for (std::size_t j = 0; j < run.path_end(kk); ++j) t.path.push_back(momentum_body(run.path[j][b]) * (L / Lb));
      out.push_back(std::move(t));
    }
    return out;
  }

  viz::MomentumSphereInput input(long kk) const {
    const RigidBodyModel& m = ctx_.scene.bodies[body_].model;
    viz::MomentumSphereInput in;
    in.inertia = m.inertia;
    if (!ctx_.runs.empty() && !ctx_.runs[0].frames.empty()) {
      in.momentum = momentum_body(ctx_.runs[0].frames[static_cast<std::size_t>(kk)][body_]);
      in.two_E = in.momentum.dot(m.inv_inertia.cwiseProduct(in.momentum));
    }
    in.camera = settings_;
    in.width_px = size_.x, in.height_px = size_.y;
    in.frame_h = ctx_.frame_h;
    in.text_scale = ctx_.text_scale();
    const scene::ViewConfig& view = ctx_.scene.render.explain.views[index_];
    in.fit_radius = kFitRadius / view.zoom;  // a zoom: less room round the ball, where its camera needs less
    in.energy_ellipsoid = view.energy_ellipsoid;
    in.trail = view.path_trail;
    in.faint_polhode = view.path_faint_polhode;
    in.line_scale = static_cast<float>(view.line_scale);
    in.levels = view.levels;
    in.level_arrows = view.level_arrows;
    in.dot_scale = static_cast<float>(view.dot_scale);
    in.dark_levels = view.dark_levels;
    in.path_on_top = view.path_on_top;
    in.hide_far_side = view.hide_far_side;
    in.tracks_under_separatrix = !view.paths_of.empty() && !view.path_on_top;  // bodies' paths as a body's own path
    return in;
  }

  const PanelContext& ctx_;
  std::size_t body_, index_;
  viz::SphereCameraSettings settings_;
  std::vector<viz::SpherePose> track_;  // the camera at each path sample
  glm::vec2 size_{1, 1};
};

}  // namespace

std::unique_ptr<Panel> make_momentum_sphere(const PanelContext& ctx, std::size_t index) {
  return std::make_unique<SpherePanel>(ctx, index);
}

}  // namespace tumble::compose
