// A scene's bodies stepped to every frame time of its clock (FrameClock), one
// run per method of [compare] (else the scene's), with sub-frame samples for
// smooth curves: what the frame composition (src/compose) draws from.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/body.hpp"
#include "scene/frame_clock.hpp"
#include "scene/scene.hpp"

namespace tumble::scene {

/// One simulated run of all bodies with one method (several in a comparison),
/// stored at every frame time t_k (k/fps, or the scene's FrameClock).
struct Run {
  std::string label;                        ///< method name(s)
  std::string title;                        ///< for a figure: "explicit Euler, order 1", "exact (closed form)"
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

}  // namespace tumble::scene
