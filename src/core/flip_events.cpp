#include "core/flip_events.hpp"

#include <algorithm>
#include <cmath>

#include "core/dynamics.hpp"
#include "core/methods/free_rotation_exact.hpp"

namespace tumble {

namespace {

double sign_of(double v) { return v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0); }

// Bisection on [a, b] with sign(f(a)) = sa ≠ 0 and f(b) of the other sign.
double bisect(const std::function<double(double)>& f, double a, double b, double sa) {
  for (int i = 0; i < 200 && b - a > 1e-12 * std::max(1.0, std::abs(b)); ++i) {
    const double mid = 0.5 * (a + b);
    const double s = sign_of(f(mid));
    if (s == sa) a = mid;
    else b = mid;  // 0 or the other sign: the change is at or before mid
  }
  return 0.5 * (a + b);
}

}  // namespace

std::vector<double> sign_change_times(const std::function<double(double)>& f, double t0, double t1, double dt) {
  std::vector<double> out;
  if (!(t1 > t0) || !(dt > 0)) return out;
  const long n = std::max(1L, static_cast<long>(std::ceil((t1 - t0) / dt)));
  double last_t = t0, last_s = sign_of(f(t0));
  for (long i = 1; i <= n; ++i) {
    const double t = i == n ? t1 : t0 + (t1 - t0) * static_cast<double>(i) / static_cast<double>(n);
    const double s = sign_of(f(t));
    if (s == 0) continue;
    if (last_s != 0 && s != last_s) out.push_back(bisect(f, last_t, t, last_s));
    last_t = t, last_s = s;
  }
  return out;
}

namespace {

// Largest |f| over [a, b], sampled `dt` apart (ends included).
double max_abs(const std::function<double(double)>& f, double a, double b, double dt) {
  const long n = std::max(1L, static_cast<long>(std::ceil((b - a) / dt)));
  double m = 0;
  for (long i = 0; i <= n; ++i) m = std::max(m, std::abs(f(a + (b - a) * static_cast<double>(i) / static_cast<double>(n))));
  return m;
}

// The sign changes of Π₂ = pi2(t) that are turn-overs: on the swing before or
// after, |Π₂| reaches |L|/√2 (e2 within 45° of ±L).
std::vector<double> turn_overs(const std::function<double(double)>& pi2, double L, double t_max, double dt) {
  const std::vector<double> c = sign_change_times(pi2, 0, t_max, dt);
  std::vector<double> swing;  // max |Π₂| on [0, c0], [c0, c1], …, [c_last, t_max]
  double a = 0;
  for (std::size_t i = 0; i <= c.size(); ++i) {
    const double b = i < c.size() ? c[i] : t_max;
    swing.push_back(max_abs(pi2, a, b, dt));
    a = b;
  }
  std::vector<double> out;
  const double big = L / std::sqrt(2.0);
  for (std::size_t i = 0; i < c.size(); ++i)
    if (swing[i] >= big || swing[i + 1] >= big) out.push_back(c[i]);
  return out;
}

}  // namespace

std::vector<double> flip_times(const RigidBodyModel& m, const BodyState& s0, const StepConfig& cfg, double t_max) {
  const double L = s0.L.norm();
  if (!m.forces.has_torque()) {
    const FreeRotationExact ex(m.inertia, s0.q, s0.L);
    const double period = ex.body_period();
    double dt = std::isfinite(period) && period > 0 ? period / 64 : 1e-3;
    dt = std::max(dt, t_max / 2e5);  // bounded work; a finer period is a blur anyway
    return turn_overs([&](double t) { return ex.momentum_body(t)[1]; }, L, t_max, dt);
  }
  // With torques: the stepped motion, sampled on a fine grid. Propagator only
  // moves forward, so each evaluation steps afresh from the last sample before it.
  const double dt = std::min(cfg.dt, 1e-3);
  const long n = static_cast<long>(std::ceil(t_max / dt));
  std::vector<BodyState> samples;
  Propagator p(m, s0, cfg);
  for (long i = 0; i <= n; ++i) samples.push_back(p.advance_to(std::min(t_max, static_cast<double>(i) * dt)));
  auto pi2 = [&](double t) {
    const long i = std::clamp(static_cast<long>(std::floor(t / dt)), 0L, n);
    const double ti = static_cast<double>(i) * dt;
    if (t <= ti) return momentum_body(samples[static_cast<std::size_t>(i)])[1];
    Propagator q(m, samples[static_cast<std::size_t>(i)], cfg);
    return momentum_body(q.advance_to(t - ti))[1];
  };
  // |L| changes under torque: the turn-over test uses the largest |L| sampled.
  double L_max = 0;
  for (const BodyState& s : samples) L_max = std::max(L_max, s.L.norm());
  return turn_overs(pi2, L_max, t_max, dt);
}

}  // namespace tumble
