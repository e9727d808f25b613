// Which simulated time each video frame shows. Frame k is at video time
// τ_k = k/fps; simulated time advances at `time_scale` s per video second,
// or at a slow-motion segment's own rate inside it. With time_scale 1 and no
// segment, frame k shows exactly k/fps (the classic render, bit for bit).
// A title card's `hold` (video s) comes first: its frames show t = 0 while
// the animation waits, and every later frame is shifted by it.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "scene/explain.hpp"

namespace tumble::scene {

class FrameClock {
 public:
  /// `segments` must be sorted, disjoint, inside [0, duration] (the loader
  /// checks); `holds` sorted by simulated time (inside a segment or not).
  FrameClock(double duration, double fps, double time_scale = 1, std::vector<SlowMotion> segments = {},
             double hold = 0, std::vector<Hold> holds = {});

  double fps() const { return fps_; }
  long count() const { return count_; }        ///< frames: 0 … ⌊τ(duration)·fps⌋
  double time(long k) const;                   ///< simulated s shown by frame k
  double hold() const { return hold_; }        ///< video s of the title card before the animation
  /// Whether frame k is on the title card (before the animation starts).
  bool on_title_card(long k) const { return static_cast<double>(k) / fps_ < hold_ - 1e-9; }
  /// Speed of frame k: simulated s per video s (the title card and a hold: 0).
  double rate(long k) const;
  /// Whether frame k is in a [[holds]] stop (the animation paused, after the title card).
  bool in_hold(long k) const { return !on_title_card(k) && rate(k) == 0; }
  double video_time(double t) const;           ///< τ(t): the first video s at which simulated t is shown
  /// The last video s at which simulated t is shown: after a hold at t, else τ(t).
  double video_time_last(double t) const;
  /// Frame showing simulated `t` exactly (within 1e-9 relative), or -1.
  long frame_at(double t) const;

 private:
  struct Piece {
    double t0, tau0, rate;  // from simulated t0 (shown at video tau0), simulated s per video s
  };
  const Piece& piece_at_video(double tau) const;
  double fps_, time_scale_, hold_;
  std::vector<Piece> pieces_;  // sorted by t0; the first starts at 0
  double tau_end_ = 0;         // video s at the end of the last piece
  long count_;
};

/// Consecutive frames played at one rate: frames first … last, simulated
/// s per video s `rate` (0 on the title card).
struct ClockSpan {
  long first = 0, last = 0;
  double rate = 0;
};
/// The clock's frames grouped into spans of one rate, in order (for `tumble info`).
std::vector<ClockSpan> clock_spans(const FrameClock& c);

/// A rate as a lecturer says it: "×1/8" for 0.125 simulated s per video s,
/// "×2" for 2, "" for real time (1) and the title card (0).
std::string speed_text(double rate);

/// Video s [first, last] during which caption `c` is up: from the first frame
/// showing its start (plus `after`) to the last showing its end (or `seconds` on).
std::pair<double, double> caption_video_span(const FrameClock& clock, const Caption& c);

struct Scene;
/// The clock of a scene's render at `fps` ([output] time_scale, [[slow_motion]]).
FrameClock frame_clock(const Scene& s, double fps);

}  // namespace tumble::scene
