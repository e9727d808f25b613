#include "scene/frame_clock.hpp"

#include "scene/scene.hpp"

#include <algorithm>
#include <cmath>

namespace tumble::scene {

FrameClock::FrameClock(double duration, double fps, double time_scale, std::vector<SlowMotion> segments)
    : fps_(fps), time_scale_(time_scale) {
  // Piecewise-constant rate; video time is its integral of 1/rate.
  double t = 0, tau = 0;
  auto add = [&](double t_end, double rate) {
    if (t_end <= t) return;
    pieces_.push_back({t, tau, rate});
    tau += (t_end - t) / rate;
    t = t_end;
  };
  for (const SlowMotion& s : segments) {
    add(std::min(s.start, duration), time_scale);
    add(std::min(s.end, duration), s.time_scale);
  }
  add(duration, time_scale);
  if (pieces_.empty()) pieces_.push_back({0, 0, time_scale});
  count_ = static_cast<long>(std::floor(tau * fps * (1 + 1e-12))) + 1;
}

double FrameClock::time(long k) const {
  const double kd = static_cast<double>(k);
  if (pieces_.size() == 1) return time_scale_ == 1 ? kd / fps_ : kd * time_scale_ / fps_;
  const double tau = kd / fps_;
  auto it = std::upper_bound(pieces_.begin(), pieces_.end(), tau, [](double v, const Piece& p) { return v < p.tau0; });
  const Piece& p = *(it == pieces_.begin() ? it : it - 1);
  return p.t0 + (tau - p.tau0) * p.rate;
}

double FrameClock::video_time(double t) const {
  auto it = std::upper_bound(pieces_.begin(), pieces_.end(), t, [](double v, const Piece& p) { return v < p.t0; });
  const Piece& p = *(it == pieces_.begin() ? it : it - 1);
  return p.tau0 + (t - p.t0) / p.rate;
}

long FrameClock::frame_at(double t) const {
  const long k = std::lround(video_time(t) * fps_);
  if (k < 0 || k >= count_) return -1;
  return std::abs(time(k) - t) <= 1e-9 * std::max(1.0, std::abs(t)) ? k : -1;
}

FrameClock frame_clock(const Scene& s, double fps) {
  return FrameClock(s.simulation.duration, fps, s.render.explain.time_scale, s.render.explain.slow_motion);
}

}  // namespace tumble::scene
