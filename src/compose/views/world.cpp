// The `world` view kind (and each cell of a scene without [[views]]): the
// bodies in space seen by the scene's camera, the overlay line in the title
// strip, the bodies' key beside them. A view with `body` shows that body
// alone, with its trails, and the readout only when it is the first body's
// (the readout's E, |L| and |ω| are the first body's). The camera keeps the scene's direction
// and backs off, if it must, until every body and arrow of the whole video is
// inside the content rectangle.
#include <algorithm>
#include <cmath>

#include "compose/camera_fit.hpp"
#include "compose/panel.hpp"
#include "compose/views/kinds.hpp"
#include "viz/palette.hpp"
#include "viz/scene_view.hpp"
#include "viz/text_layout.hpp"

namespace tumble::compose {

namespace {

constexpr double kMargin = 0.04;  // of the content's half size, kept clear at each edge
constexpr long kFitSamples = 240;  // frames looked at to fit the camera
constexpr double kClosest = 0.1;   // a camera moves at most this much closer to fit
constexpr double kFillMargin = 0.1;  // room around what a camera moved closer frames
constexpr float kSeeThroughAlpha = 0.6f;  // a see_through view's surfaces: solid enough to read, an axis behind them seen

class WorldPanel : public Panel {
 public:
  WorldPanel(const PanelContext& ctx, std::size_t run, bool keyed, const scene::ViewConfig* vc = nullptr,
             std::optional<std::size_t> only = std::nullopt)
      : ctx_(ctx), run_(run), keyed_(keyed), vc_(vc), own_(vc && vc->camera.position ? &vc->camera : nullptr),
        across_(vc && vc->camera.across != 0 ? &vc->camera : nullptr), only_(only) {}
  std::string name() const override { return "world"; }
  // A view of one body is keyed as a classic scene's legend: arrow swatches, and the box.
  std::vector<viz::KeyEntry> key() const override {
    if (!keyed_) return {};
    std::vector<viz::KeyEntry> k = bodies_key(ctx_, only_, only_.has_value());
    if (const auto box = box_key(ctx_); box && only_) k.push_back(*box);
    return k;
  }
  // A view's own readout (of its body), else the frame's overlay where the view shows the first body.
  std::vector<std::string> overlay(long k) const override {
    if (vc_ && vc_->readout) return ctx_.world.readout(run_, k, *only_, *vc_->readout);
    return read_out() ? ctx_.world.overlay(run_, k) : std::vector<std::string>{};
  }
  int overlay_lines() const override {
    if (vc_ && vc_->readout) return WorldViews::readout_lines(*vc_->readout);
    return read_out() ? ctx_.world.overlay_lines(run_) : 0;
  }

  void fit(glm::vec2 size) override {
    size_ = size;
    const double aspect = size.x / std::max(size.y, 1.0f);
    camera_ = own_ ? view_camera(*own_) : scene_camera(ctx_.scene, ctx_.runs, aspect);
    if (across_) {
      // The scene camera's target and distance, turned to look across the first body's L
      // (a view of one body: at that body, across its L).
      const scene::CameraConfig& sc = ctx_.scene.render.camera;
      const scene::Body& b = ctx_.scene.bodies[only_.value_or(0)];
      // One body: from twice the distance at which its box fills the view (the fit then comes closer).
      const double dist = only_ ? 2.3 * viz::box_radius(b.model) / std::sin(glm::radians(camera_.fov_y_deg) / 2)
                                : glm::length(camera_.position - camera_.target) * 2;
      const Eigen::Vector3d target =
          only_ ? b.initial.c : Eigen::Vector3d(camera_.target.x, camera_.target.y, camera_.target.z);
      camera_ = across_camera(target, b.initial.L, across_->across,
                              across_->azimuth_deg.value_or(sc.azimuth_deg), across_->elevation_deg.value_or(sc.elevation_deg),
                              dist, camera_.fov_y_deg, across_->roll_deg.value_or(0));
    }
    // The cells of a [compare] grid share one camera, fitted to every run, so
    // the methods' bodies are drawn at one scale side by side.
    const bool grid = !ctx_.scene.render.compare_methods.empty() && ctx_.runs.size() > 1 && run_ < ctx_.runs.size();
    std::vector<Shot> shots;
    Outlines outlines;
    const long n = ctx_.world.clock().count();
    for (std::size_t r = 0; r < ctx_.runs.size(); ++r) {
      if (!grid && r != run_) continue;
      for (long i = 0; i < std::min(n, kFitSamples); ++i) {
        const long k = n <= kFitSamples ? i : i * (n - 1) / (kFitSamples - 1);
        const viz::View v = ctx_.world.view(r, k, camera_, int(size.x), int(size.y), only_);
        shots.push_back(solid_shot(v, outlines));
      }
    }
    double f = backoff(shots, aspect, margins(size), closest(), tip_margins(size));
    // A fitted camera also moves sideways, so that the whole video's content
    // is centred and comes as close as it can; a camera placed by hand stays.
    for (int round = 0; round < 2 && closest() < 1; ++round) {
      camera_ = centred(camera_, shots, aspect, f);
      for (Shot& s : shots) s.camera = camera_;
      f = backoff(shots, aspect, margins(size), closest(), tip_margins(size));
    }
    camera_ = backed_off(camera_, f);
  }

  // A camera set for the whole frame (the scene's) frames its view of a
  // laid-out frame loosely, and so does an automatic one (bounding spheres):
  // both move closer until the whole video's bodies and arrows fill the
  // content. A classic single view keeps the scene's camera, backed off only
  // where something would leave the frame.
  double closest() const {
    if (own_) return 1.0;  // the view's own camera is where its author put it (backed off only if something leaves)
    const bool laid_out = !ctx_.scene.render.explain.views.empty() || ctx_.runs.size() > 1;
    return laid_out || ctx_.scene.render.camera.automatic || ctx_.scene.render.camera.across != 0 || across_ ? kClosest
                                                                                                         : 1.0;
  }
  // Room at the edges: the margin, and above and below a name label's line
  // (labels sit beside their bodies: above or below, or at their sides).
  Margins margins(glm::vec2 size) const {
    const double m = closest() < 1 ? kFillMargin : kMargin;
    if (!ctx_.scene.render.explain.labels) return m;
    const double line = 1.2 * 1.1 * ctx_.world.font_px();
    return {m, std::max(m, line / (0.5 * std::max(size.y, 1.0f)))};
  }
  // Arrows carry their names past their tips: room for a name beside the
  // tips alone (the bodies keep the plain margin, so they are not shrunk for
  // it). A name with no room along its arrow turns beside the tip
  // (viz::label_arrow_tips): a name's width across, half a line up and down.
  Margins tip_margins(glm::vec2 size) const {
    if (vc_ && !vc_->tip_names) return 0.0;
    const double px = viz::text_px(viz::TextRole::label, ctx_.frame_h, ctx_.text_scale());
    return {1.4 * px / (0.5 * std::max(size.x, 1.0f)), 0.6 * px / (0.5 * std::max(size.y, 1.0f))};
  }

  viz::View content(long k) const override {
    viz::View v = ctx_.world.view(run_, k, camera_, int(size_.x), int(size_.y), only_);
    if (only_)
      for (viz::PolylineItem& p : ctx_.world.trails(run_, k, *only_, vc_ ? vc_->trail_axes : std::nullopt,
                                                    vc_ ? vc_->trail_seconds : std::nullopt)) {
        if (vc_) p.width_px *= static_cast<float>(vc_->trail_width);
        if (vc_ && vc_->trail_width > 1) p.fade = false;  // a bold trail is one colour: its whole circle reads
        v.polylines.push_back(std::move(p));
      }
    // See-through surfaces: an axis behind or inside the body (a stem seen end on) stays seen.
    if (vc_ && vc_->see_through)
      for (viz::SurfaceItem& sf : v.surfaces)
        if (sf.name.empty()) {
          sf.color.a = std::min(sf.color.a, kSeeThroughAlpha);
          sf.see_through = true;
        }
    // A view may leave out the principal box's outline (a surface's box: no faces, only edges).
    if (vc_ && !vc_->box)
      std::erase_if(v.boxes, [](const viz::BoxItem& b) { return b.face.a == 0.0f; });
    v.name = name();
    // A view of small bodies may draw its arrows thicker, and leave their names to the key.
    for (viz::ArrowItem& a : v.arrows) {
      if (!vc_) break;
      a.radius *= vc_->line_scale * (a.name == "L" ? vc_->L_width : a.name == "omega" ? vc_->omega_width : 1.0);
      if (!vc_->tip_names) a.tip.clear();
    }
    return v;
  }

 private:
  const PanelContext& ctx_;
  std::size_t run_;
  bool keyed_;
  const scene::ViewConfig* vc_;  // the view's options (none: a classic view or a [compare] cell)
  const scene::ViewCamera* own_;  // the view's own camera (a world view's `camera` table), else the scene's
  const scene::ViewCamera* across_;  // the view's camera across L
  std::optional<std::size_t> only_;  // the view's body alone
  glm::vec2 size_{1, 1};

  bool read_out() const { return !only_ || *only_ == 0; }

  viz::Camera view_camera(const scene::ViewCamera& c) const {
    auto g = [](const std::array<double, 3>& a) { return glm::dvec3(a[0], a[1], a[2]); };
    viz::Camera cam;
    cam.position = g(*c.position);
    cam.target = g(c.target.value_or(std::array<double, 3>{}));
    cam.up = g(c.up.value_or(std::array<double, 3>{0, 0, 1}));
    cam.fov_y_deg = c.fov_y_deg.value_or(ctx_.scene.render.camera.fov_y_deg);
    return cam;
  }
  viz::Camera camera_;
};

}  // namespace

std::vector<viz::KeyEntry> bodies_key(const PanelContext& ctx, std::optional<std::size_t> only, bool arrows) {
  std::vector<std::pair<std::string, viz::Color>> bodies;
  // A body is named beside it (labels), or by the view's title: the key names bodies only when neither does.
  const bool named = ctx.scene.render.explain.labels || only || ctx.scene.bodies.size() == 1;
  for (std::size_t i = 0; i < ctx.scene.bodies.size() && !named; ++i) {
    if (only && i != *only) continue;
    bodies.emplace_back(ctx.scene.bodies[i].label.empty() ? ctx.scene.bodies[i].name : ctx.scene.bodies[i].label,
                        body_key_color(ctx.scene.bodies[i]));  // the display name
  }
  return viz::bodies_key(ctx.world.draw(), bodies, arrows);
}

viz::Color body_key_color(const scene::Body& b) {
  const Eigen::Vector3f c = 0.75f * b.color.cast<float>();
  return {c.x(), c.y(), c.z(), 1.0f};
}

std::optional<viz::KeyEntry> box_key(const PanelContext& ctx) {
  const viz::DrawOptions& draw = ctx.world.draw();
  if (!draw.box.value_or(false) || !draw.surface || ctx.scene.bodies.empty()) return std::nullopt;
  const Eigen::Vector3f c = 0.45f * ctx.scene.bodies.front().color.cast<float>();
  return viz::KeyEntry{viz::Swatch::line, {viz::Color(c.x(), c.y(), c.z(), 0.5f)}, "box along the principal axes"};
}

viz::Color run_color(const scene::Run& run) {
  // Crimson, dark ochre (4.7:1 on white) and violet: apart from the axes' vermillion, green and blue, L's black and each other.
  static const std::pair<const char*, viz::Color> kColors[] = {
      {"euler", {0.80f, 0.08f, 0.22f, 1}}, {"rk4", {0.58f, 0.43f, 0.0f, 1}}, {"splitting", {0.50f, 0.22f, 0.72f, 1}}};
  for (const auto& [label, color] : kColors)
    if (run.label == label) return color;
  return viz::color_of(viz::Meaning::ink);
}

std::unique_ptr<Panel> make_world(const PanelContext& ctx, std::size_t index) {
  const scene::ViewConfig& v = ctx.scene.render.explain.views[index];
  const std::optional<std::size_t> only = v.body.empty() ? std::nullopt : std::optional<std::size_t>(view_body(ctx, index));
  return std::make_unique<WorldPanel>(ctx, 0, ctx.scene.render.explain.key, &v, only);
}

std::unique_ptr<Panel> make_run_panel(const PanelContext& ctx, std::size_t r) {
  // A classic view has the legend line for its key.
  return std::make_unique<WorldPanel>(ctx, r, false);
}

}  // namespace tumble::compose
