// The views of bodies in space (world, body_frame, each run of a [compare]
// grid): bodies, arrows, trails, grid, name labels and the overlay line, from
// a scene's runs at frame k, seen by a given camera. GL-free.
#pragma once

#include <cstddef>
#include <vector>

#include "scene/frame_clock.hpp"
#include "scene/frame_runs.hpp"
#include "scene/scene.hpp"
#include "viz/body_look.hpp"
#include "viz/draw_list.hpp"
#include "viz/draw_options.hpp"
#include "viz/scene_view.hpp"

namespace tumble::compose {

/// The scene's camera for a viewport of `aspect` (width/height): automatic
/// (frames every body over all runs) or as configured.
viz::Camera scene_camera(const scene::Scene& s, const std::vector<scene::Run>& runs, double aspect);

class WorldViews {
 public:
  /// `font_px`: the overlay's and labels' text size. Keeps references to `s` and `runs`.
  WorldViews(const scene::Scene& s, const std::vector<scene::Run>& runs, const scene::FrameClock& clock, float font_px);

  /// Run `r`'s view at frame k (bodies, grid, overlay, labels) seen by
  /// `camera`; its text starts `top_px` below the viewport's top (room for a title).
  viz::View view(std::size_t r, long k, const viz::Camera& camera, int width_px, int height_px, float top_px = 0) const;

  const scene::FrameClock& clock() const { return clock_; }
  float font_px() const { return font_px_; }
  const viz::DrawOptions& draw() const { return draw_; }

 private:
  const scene::Scene& scene_;
  const std::vector<scene::Run>& runs_;
  scene::FrameClock clock_;
  float font_px_;
  viz::DrawOptions draw_;
  std::vector<viz::TrailRecorder> trails_;  // per run, fed with every frame from 0
  std::vector<viz::BodyLook> looks_;        // per body: surfaces, visible particles
};

}  // namespace tumble::compose
