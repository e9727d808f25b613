// Which simulated time each video frame shows. Frame k is at video time
// τ_k = k/fps; simulated time advances at `time_scale` s per video second,
// or at a slow-motion segment's own rate inside it. With time_scale 1 and no
// segment, frame k shows exactly k/fps (the classic render, bit for bit).
#pragma once

#include <vector>

#include "scene/explain.hpp"

namespace tumble::scene {

class FrameClock {
 public:
  /// `segments` must be sorted, disjoint, inside [0, duration] (the loader checks).
  FrameClock(double duration, double fps, double time_scale = 1, std::vector<SlowMotion> segments = {});

  double fps() const { return fps_; }
  long count() const { return count_; }        ///< frames: 0 … ⌊τ(duration)·fps⌋
  double time(long k) const;                   ///< simulated s shown by frame k
  double video_time(double t) const;           ///< τ(t): video s at which simulated t is shown
  /// Frame showing simulated `t` exactly (within 1e-9 relative), or -1.
  long frame_at(double t) const;

 private:
  struct Piece {
    double t0, tau0, rate;  // from simulated t0 (shown at video tau0), simulated s per video s
  };
  double fps_, time_scale_;
  std::vector<Piece> pieces_;  // sorted by t0; the first starts at 0
  long count_;
};

struct Scene;
/// The clock of a scene's render at `fps` ([output] time_scale, [[slow_motion]]).
FrameClock frame_clock(const Scene& s, double fps);

}  // namespace tumble::scene
