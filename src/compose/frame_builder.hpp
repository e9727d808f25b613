// Everything drawn in frame k of a scene, as a GL-free viz::DrawList: the
// classic view (or [compare] grid) of bodies in space, or the scene's
// [[views]] with their keys, captions and title card. What MuJoCo's mjv is to
// mjr: src/render draws the list, tests inspect it without GL.
#pragma once

#include <memory>
#include <vector>

#include "compose/world_views.hpp"
#include "scene/frame_clock.hpp"
#include "scene/frame_runs.hpp"
#include "scene/scene.hpp"
#include "viz/draw_list.hpp"

namespace tumble::compose {

class ExplainViews;

class FrameBuilder {
 public:
  /// Keeps references to `s` and `runs` (scene::simulate_runs at `fps`).
  FrameBuilder(const scene::Scene& s, const std::vector<scene::Run>& runs, double fps, int width, int height);
  ~FrameBuilder();
  viz::DrawList build(long k) const;

  const scene::FrameClock& clock() const { return world_.clock(); }
  float font_px() const { return world_.font_px(); }

 private:
  const scene::Scene& scene_;
  const std::vector<scene::Run>& runs_;
  int width_, height_, columns_, rows_;
  viz::Camera camera_;
  WorldViews world_;
  std::unique_ptr<ExplainViews> explain_;   // [[views]], captions, title (null without them)
};

}  // namespace tumble::compose
