#include "compose/frame_builder.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "compose/explain_views.hpp"
#include "viz/text_layout.hpp"

namespace tumble::compose {

namespace {

int grid_columns(std::size_t runs) {
  const int n = std::max<int>(1, static_cast<int>(runs));
  return static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
}

// The overlay's and labels' size: explanatory views use the label role's (in
// proportion to the frame), the classic view a size per grid cell.
float overlay_px(const scene::Scene& s, int height, int rows) {
  return s.render.explain.views.empty() ? std::clamp(static_cast<float>(height) / rows / 24.0f, 11.0f, 18.0f)
                                        : viz::text_px(viz::TextRole::label, height);
}

int grid_rows(std::size_t runs) {
  const int n = std::max<int>(1, static_cast<int>(runs)), c = grid_columns(runs);
  return (n + c - 1) / c;
}

}  // namespace

FrameBuilder::~FrameBuilder() = default;

FrameBuilder::FrameBuilder(const scene::Scene& s, const std::vector<scene::Run>& runs, double fps, int width, int height)
    : scene_(s),
      runs_(runs),
      width_(width),
      height_(height),
      columns_(grid_columns(runs.size())),
      rows_(grid_rows(runs.size())),
      world_(s, runs, scene::frame_clock(s, fps), overlay_px(s, height, grid_rows(runs.size()))) {
  const double aspect = (static_cast<double>(width) / columns_) / (static_cast<double>(height) / rows_);
  camera_ = scene_camera(s, runs, aspect);
  if (!s.render.explain.views.empty() || !s.render.explain.captions.empty() || s.render.explain.title.hold > 0)
    explain_ = std::make_unique<ExplainViews>(world_, s, runs, width, height);
}

viz::DrawList FrameBuilder::build(long k) const {
  viz::DrawList dl;
  const Eigen::Vector3d& bg = scene_.render.output.background;
  dl.background = {static_cast<float>(bg.x()), static_cast<float>(bg.y()), static_cast<float>(bg.z()), 1.0f};
  dl.columns = columns_;
  const viz::Color ink{0.12f, 0.13f, 0.16f, 1.0f};
  if (explain_ && explain_->title_card(dl, k)) return dl;  // the animation waits
  if (explain_ && !scene_.render.explain.views.empty()) {
    explain_->add_views(dl, k);
  } else {
    for (size_t r = 0; r < runs_.size(); ++r)
      dl.views.push_back(world_.view(r, k, camera_, width_ / columns_, height_ / rows_));
  }
  const viz::DrawOptions& draw = world_.draw();
  if (scene_.render.draw.legend && draw.axes) {
    std::string legend = "principal axes:  red = smallest moment   green = intermediate   blue = largest";
    if (draw.angular_momentum) legend += "   orange = L";
    if (draw.omega) legend += "   purple = omega";
    dl.texts.push_back({legend, {12.0f, static_cast<float>(height_) - 26.0f}, 15.0f, ink});
  }
  if (explain_) explain_->add_text(dl, k);
  return dl;
}

}  // namespace tumble::compose
