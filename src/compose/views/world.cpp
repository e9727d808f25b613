// The `world` view kind (and each cell of a scene without [[views]]): the
// bodies in space seen by the scene's camera, the overlay line in the title
// strip, the bodies' key beside them. The camera keeps the scene's direction
// and backs off, if it must, until every body and arrow of the whole video is
// inside the content rectangle.
#include <algorithm>

#include "compose/camera_fit.hpp"
#include "compose/panel.hpp"
#include "compose/views/kinds.hpp"

namespace tumble::compose {

namespace {

constexpr double kMargin = 0.04;  // of the content's half size, kept clear at each edge
constexpr long kFitSamples = 240;  // frames looked at to fit the camera

class WorldPanel : public Panel {
 public:
  WorldPanel(const PanelContext& ctx, std::size_t run, bool keyed) : ctx_(ctx), run_(run), keyed_(keyed) {}
  std::string name() const override { return "world"; }
  std::vector<viz::KeyEntry> key() const override { return keyed_ ? bodies_key(ctx_, std::nullopt) : std::vector<viz::KeyEntry>{}; }
  std::vector<std::string> overlay(long k) const override { return ctx_.world.overlay(run_, k); }
  int overlay_lines() const override { return ctx_.world.overlay_lines(run_); }

  void fit(glm::vec2 size) override {
    size_ = size;
    const double aspect = size.x / std::max(size.y, 1.0f);
    camera_ = scene_camera(ctx_.scene, ctx_.runs, aspect);
    std::vector<Shot> shots;
    const long n = ctx_.world.clock().count();
    for (long i = 0; i < std::min(n, kFitSamples); ++i) {
      const long k = n <= kFitSamples ? i : i * (n - 1) / (kFitSamples - 1);
      const viz::View v = ctx_.world.view(run_, k, camera_, int(size.x), int(size.y));
      shots.push_back({v.camera, solid_points(v)});
    }
    camera_ = backed_off(camera_, backoff(shots, aspect, kMargin));
  }

  viz::View content(long k) const override {
    viz::View v = ctx_.world.view(run_, k, camera_, int(size_.x), int(size_.y));
    v.name = name();
    return v;
  }

 private:
  const PanelContext& ctx_;
  std::size_t run_;
  bool keyed_;
  glm::vec2 size_{1, 1};
  viz::Camera camera_;
};

}  // namespace

std::vector<viz::KeyEntry> bodies_key(const PanelContext& ctx, std::optional<std::size_t> only) {
  std::vector<std::pair<std::string, viz::Color>> bodies;
  for (std::size_t i = 0; i < ctx.scene.bodies.size(); ++i) {
    if (only && i != *only) continue;
    const Eigen::Vector3f c = 0.75f * ctx.scene.bodies[i].color.cast<float>();
    bodies.emplace_back(ctx.scene.bodies[i].name, viz::Color(c.x(), c.y(), c.z(), 1.0f));
  }
  return viz::bodies_key(ctx.world.draw(), bodies);
}

std::unique_ptr<Panel> make_world(const PanelContext& ctx, std::size_t) {
  return std::make_unique<WorldPanel>(ctx, 0, ctx.scene.render.explain.key);
}

std::unique_ptr<Panel> make_run_panel(const PanelContext& ctx, std::size_t r) {
  // A classic view has the legend line for its key.
  return std::make_unique<WorldPanel>(ctx, r, false);
}

}  // namespace tumble::compose
