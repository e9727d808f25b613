// The views of bodies in space (world, body_frame, each run of a [compare]
// grid): bodies, arrows, trails, grid, name labels and the overlay line, from
// a scene's runs at frame k, seen by a given camera. GL-free.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
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
/// The same from each body's centres of mass over the run (`centres[i]` for
/// body i, world, m), for a caller that holds no runs (the glTF export).
viz::Camera scene_camera(const scene::Scene& s, const std::vector<std::vector<glm::dvec3>>& centres, double aspect);

/// A camera looking across `L` at `target` (`sign` +1: L up in the picture,
/// −1: down): from `azimuth_deg` around L (0: the side nearest world −y) and
/// `elevation_deg` towards it, `distance` m away. L then lies in (or, with an
/// elevation, near) the picture plane, as long as the picture is high;
/// `roll_deg` turns L clockwise in the picture (90: L points right, along a wide picture).
viz::Camera across_camera(const Eigen::Vector3d& target, const Eigen::Vector3d& L, int sign, double azimuth_deg,
                          double elevation_deg, double distance, double fov_y_deg, double roll_deg = 0);

/// What is drawn of body `b` (its surfaces and colours; its visible particles if `particles`), once per body.
viz::BodyLook body_look(const scene::Body& b, bool particles);

/// The exact solution's body in the other methods' cells of a [compare] grid:
/// a cool slate grey, translucent, so it reads as "where the body should be" and not
/// as a second body of the method's own colour; dark enough to stand out on the pale background.
inline constexpr viz::Color kGhostColor{0.30f, 0.35f, 0.46f, 0.38f};
/// The exact solution's path on a comparison's momentum sphere: its ghost's grey, opaque.
inline constexpr viz::Color kExactPathColor{0.30f, 0.35f, 0.46f, 1.0f};

class WorldViews {
 public:
  /// `font_px`: the overlay's and labels' text size. Keeps references to `s` and `runs`.
  WorldViews(const scene::Scene& s, const std::vector<scene::Run>& runs, const scene::FrameClock& clock, float font_px);

  /// Run `r`'s bodies at frame k (boxes, arrows, trails, grid, name labels)
  /// seen by `camera` in a width × height px rectangle; `only`: that body alone
  /// (a view of one body), without trails.
  viz::View view(std::size_t r, long k, const viz::Camera& camera, int width_px, int height_px,
                 std::optional<std::size_t> only = std::nullopt) const;
  /// Run `r`'s trails of body `b`'s axis tips at frame k (as the scene draws them), in space.
  /// `axes`: which axes' tips (none: [draw] trail_axes); `seconds`: how long (none: [draw] trails).
  std::vector<viz::PolylineItem> trails(std::size_t r, long k, std::size_t b,
                                        std::optional<std::array<bool, 3>> axes = std::nullopt,
                                        std::optional<double> seconds = std::nullopt) const;
  /// Run `r`'s overlay at frame k: its line (time, method, step, energy error,
  /// as the scene asks) and, once it has diverged, where it stopped.
  std::vector<std::string> overlay(std::size_t r, long k) const;
  /// Body b's own readout in run r at frame k: `items` of that body alone (a
  /// view's `readout`: no energy error, method or step), each item on a line of its own.
  std::vector<std::string> readout(std::size_t r, long k, std::size_t b, const scene::OverlayItems& items) const;
  /// How many lines readout(·, ·, ·, items) has (state takes two).
  static int readout_lines(const scene::OverlayItems& items);
  static std::vector<scene::OverlayItems> readout_items(const scene::OverlayItems& items);
  /// How many lines overlay(r, ·) has at most.
  int overlay_lines(std::size_t r) const;

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
  viz::GridItem grid_{};                    // the ground, fixed for the whole video
};

/// The ground grid ([draw] grid): a fixed plane under the lowest point any body reaches in `runs`.
viz::GridItem ground_grid(const scene::Scene& s, const std::vector<scene::Run>& runs);

}  // namespace tumble::compose
