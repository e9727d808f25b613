// `tumble render`: simulate a scene at its frame times, draw each frame
// headless, write PNGs atomically, a manifest and a video.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/body.hpp"
#include "scene/frame_clock.hpp"
#include "scene/scene.hpp"
#include "viz/draw_list.hpp"
#include "viz/scene_view.hpp"

namespace tumble::run {

/// One simulated run of all bodies with one method (several in a comparison),
/// stored at every frame time t_k (k/fps, or the scene's FrameClock).
struct Run {
  std::string label;                        ///< method name(s)
  std::string step_label;                   ///< "dt = 0.001 s", "rtol = 1e-08", "closed form" (per body, joined)
  std::vector<std::vector<BodyState>> frames;  ///< [frame][body]
  std::vector<double> energy0;              ///< per body, J
  std::optional<std::string> diverged;      ///< message, when the run stopped early
  std::vector<std::string> auto_notes;      ///< "body 'x': <why auto picked its method>"
  /// Smooth curves (trails, polhodes, the momentum path): every sample in time
  /// order, the frames and sub-frame samples between them, [sample][body].
  /// Filled only when the scene draws such curves (trails or [[views]]).
  std::vector<std::vector<BodyState>> path;
  std::vector<double> path_t;               ///< s, simulated time of each path sample
  std::vector<std::size_t> path_of_frame;   ///< path index of frame k's sample
  /// Path samples up to and including frame k.
  std::size_t path_end(long k) const { return path_of_frame[static_cast<std::size_t>(k)] + 1; }
};

/// Sub-frame samples between two frames h apart (s) so that no body turns by
/// more than kMaxTurnPerSample (rad) from one curve point to the next, judged by
/// |omega_world| at the earlier frame (an axis tip, Π and ω turn no faster than
/// |omega| for a free body). Depends only on the state, so a frame range
/// samples exactly as a full run does. At most kMaxSubSamples − 1 between frames.
inline constexpr double kMaxTurnPerSample = 0.05;  // rad (about 3°)
inline constexpr int kMaxSubSamples = 32;
int sub_samples(const std::vector<const RigidBodyModel*>& models, const std::vector<BodyState>& states, double h);

/// Simulates `runs` (one per method of [compare], else the scene's) up to
/// `frame_count` frames of the scene's clock at `fps`. A diverging run keeps its frames so far.
std::vector<Run> simulate_runs(const scene::Scene& s, long frame_count, double fps);

class ExplainViews;

/// What the scene's [draw] asks to draw, as viz takes it.
viz::DrawOptions draw_options(const scene::DrawConfig& d);

/// The scene's camera for a viewport of `aspect` (width/height): automatic
/// (frames every body over all runs) or as configured.
viz::Camera scene_camera(const scene::Scene& s, const std::vector<Run>& runs, double aspect);

/// Everything drawn for frame k (GL-free, so tests can inspect it).
class FrameBuilder {
 public:
  FrameBuilder(const scene::Scene& s, const std::vector<Run>& runs, double fps, int width, int height);
  ~FrameBuilder();
  viz::DrawList build(long k) const;

  /// Run `r`'s world view at frame k (bodies, grid, overlay, labels) seen by
  /// `camera`; its text starts `top_px` below the viewport's top (room for a title).
  /// `only_body`: draw that body alone (a body_frame view shows its own body only).
  viz::View world_view(std::size_t r, long k, const viz::Camera& camera, int width_px, int height_px,
                       float top_px = 0, std::optional<std::size_t> only_body = std::nullopt) const;
  const scene::FrameClock& clock() const { return clock_; }
  float font_px() const { return font_px_; }

 private:
  const scene::Scene& scene_;
  const std::vector<Run>& runs_;
  double fps_;
  scene::FrameClock clock_;
  int width_, height_, columns_, rows_;
  float font_px_;  // overlay text size, px
  viz::DrawOptions draw_;
  viz::Camera camera_;
  std::vector<viz::TrailRecorder> trails_;  // per run, fed with every frame from 0
  std::unique_ptr<ExplainViews> explain_;   // [[views]], captions, title (null without them)
  std::vector<viz::BodyLook> looks_;        // per body: surfaces, visible particles
  viz::GridItem grid_{};                    // the ground, fixed for the whole video
};

/// The ground grid ([draw] grid): a fixed plane under the lowest point any body reaches in `runs`.
viz::GridItem ground_grid(const scene::Scene& s, const std::vector<Run>& runs);

/// Parses "A:B" (inclusive, either end may be empty) against `count` frames.
std::pair<long, long> parse_frame_range(const std::string& spec, long count);

}  // namespace tumble::run
