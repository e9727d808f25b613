#include "scene/frame_clock.hpp"

#include "scene/scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tumble::scene {

FrameClock::FrameClock(double duration, double fps, double time_scale, std::vector<SlowMotion> segments,
                       double hold, std::vector<Hold> holds)
    : fps_(fps), time_scale_(time_scale), hold_(std::max(hold, 0.0)) {
  // Piecewise-constant rate; video time is its integral of 1/rate. A hold is
  // a piece of rate 0 that lasts its own video time.
  double t = 0, tau = hold_;
  std::size_t next_hold = 0;
  auto add = [&](double t_end, double rate) {
    while (next_hold < holds.size() && holds[next_hold].at <= t_end) {
      const Hold& h = holds[next_hold++];
      if (h.at > t) pieces_.push_back({t, tau, rate}), tau += (h.at - t) / rate, t = h.at;
      if (h.hold > 0) pieces_.push_back({t, tau, 0.0}), tau += h.hold;
    }
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
  if (pieces_.empty()) pieces_.push_back({0, hold_, time_scale});
  tau_end_ = tau;
  count_ = static_cast<long>(std::floor(tau * fps * (1 + 1e-12))) + 1;
}

const FrameClock::Piece& FrameClock::piece_at_video(double tau) const {
  auto it = std::upper_bound(pieces_.begin(), pieces_.end(), tau, [](double v, const Piece& p) { return v < p.tau0; });
  return *(it == pieces_.begin() ? it : it - 1);
}

double FrameClock::time(long k) const {
  const double kd = static_cast<double>(k);
  if (on_title_card(k)) return 0;
  if (pieces_.size() == 1 && hold_ == 0) return time_scale_ == 1 ? kd / fps_ : kd * time_scale_ / fps_;
  const double tau = kd / fps_;
  const Piece& p = piece_at_video(tau);
  return p.t0 + (tau - p.tau0) * p.rate;
}

double FrameClock::rate(long k) const { return on_title_card(k) ? 0 : piece_at_video(static_cast<double>(k) / fps_).rate; }

double FrameClock::video_time(double t) const {
  // The first piece that shows t: one starting exactly at t (a hold there), else the last starting before it.
  auto it = std::lower_bound(pieces_.begin(), pieces_.end(), t, [](const Piece& p, double v) { return p.t0 < v; });
  const Piece& p = it != pieces_.end() && it->t0 == t ? *it : *(it == pieces_.begin() ? it : it - 1);
  return p.rate > 0 ? p.tau0 + (t - p.t0) / p.rate : p.tau0;
}

double FrameClock::video_time_last(double t) const {
  auto it = std::upper_bound(pieces_.begin(), pieces_.end(), t, [](double v, const Piece& p) { return v < p.t0; });
  if (it == pieces_.begin()) return video_time(t);
  const Piece& p = *(it - 1);
  if (p.rate > 0) return p.tau0 + (t - p.t0) / p.rate;
  return it == pieces_.end() ? tau_end_ : it->tau0;  // a hold at the very end lasts to the end of the video
}

std::pair<double, double> caption_video_span(const FrameClock& clock, const Caption& c) {
  const double first = clock.video_time(c.start) + c.after;
  return {first, c.seconds > 0 ? first + c.seconds : clock.video_time_last(c.end)};
}

long FrameClock::frame_at(double t) const {
  const long k = std::lround(video_time(t) * fps_);
  if (k < 0 || k >= count_) return -1;
  return std::abs(time(k) - t) <= 1e-9 * std::max(1.0, std::abs(t)) ? k : -1;
}

std::vector<ClockSpan> clock_spans(const FrameClock& c) {
  std::vector<ClockSpan> out;
  for (long k = 0; k < c.count(); ++k) {
    const double r = c.rate(k);
    if (out.empty() || out.back().rate != r || c.on_title_card(out.back().last) != c.on_title_card(k) ||
        (r == 0 && c.time(k) != c.time(out.back().last)))
      out.push_back({k, k, r});
    else out.back().last = k;
  }
  return out;
}

std::string speed_text(double rate) {
  if (!(rate > 0) || std::abs(rate - 1) < 1e-12) return "";
  char b[32];
  const double inv = 1 / rate;
  if (rate < 1 && std::abs(inv - std::round(inv)) < 1e-6 * inv) std::snprintf(b, sizeof b, "×1/%.0f", inv);
  else std::snprintf(b, sizeof b, "×%.3g", rate);
  return b;
}

FrameClock frame_clock(const Scene& s, double fps) {
  return FrameClock(s.simulation.duration, fps, s.render.explain.time_scale, s.render.explain.slow_motion,
                    s.render.explain.title.hold, s.render.explain.holds);
}

}  // namespace tumble::scene
