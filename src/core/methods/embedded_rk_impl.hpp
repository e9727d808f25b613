// The engine behind embedded_rk.hpp: the two systems (torque-free: (q, Π) only,
// c and P in closed form; forced: (q, Π, c, P) by body_rate) and the step
// control shared by the pairs (rk45.cpp, dop853.cpp). Private to core.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include <Eigen/Core>

#include "core/body_frame.hpp"
#include "core/dynamics.hpp"
#include "core/methods/embedded_rk.hpp"
#include "core/error.hpp"

namespace tumble::erk {

template <int N>
using Vec = Eigen::Matrix<double, N, 1>;

// Layout: q (x, y, z, w) 0..3, Π 4..6, then (forced) c 7..9, P 10..12.
/// Error scales shared by both systems: the floors (atol times the body's own
/// scales) fixed at the start, so the norm is relative to the state.
struct Scales {
  double pi0 = 1, gyration = 1, momentum = 1;  // kg·m²/s, m, kg·m/s
  Scales() = default;
  Scales(const RigidBodyModel& m, const BodyState& s0) {
    const Eigen::Vector3d w = m.inv_inertia.cwiseProduct(momentum_body(s0));
    // A body at rest still has a scale: its largest moment turning at 1 rad/s.
    pi0 = std::max(momentum_body(s0).norm(), m.inertia.maxCoeff());
    gyration = std::sqrt(m.inertia.sum() / (2 * m.mass));
    momentum = std::max(s0.P.norm(), m.mass * gyration * std::max(w.norm(), 1.0));
  }
};

/// Largest scaled error over the groups of `e` (y, y1: the step's ends):
/// orientation 2|δq| (rad), then |δv| / (atol·floor + rtol·max(|v|, |v1|)).
/// Compared squared, one square root per group's scale and one at the end
/// (the norm runs once per step: sqrt is a good part of its cost).
template <int N>
double group_error(const Vec<N>& e, const Vec<N>& y, const Vec<N>& y1, const Scales& s, const AdaptiveOptions& o) {
  auto rel2 = [&](int i, double floor) {
    const double v = std::sqrt(std::max(y.template segment<3>(i).squaredNorm(), y1.template segment<3>(i).squaredNorm()));
    const double scale = o.atol * floor + o.rtol * v;
    return e.template segment<3>(i).squaredNorm() / (scale * scale);
  };
  const double q = 0.5 * (o.atol + o.rtol);
  double r2 = std::max(e.template head<4>().squaredNorm() / (q * q), rel2(4, s.pi0));
  if constexpr (N == 13) r2 = std::max({r2, rel2(7, s.gyration), rel2(10, s.momentum)});
  return std::sqrt(r2);
}

/// Torque-free: only (q, Π) are integrated; c = c0 + (t − t0) P/M, P = P0.
struct FreeSystem {
  static constexpr int N = 7;
  Eigen::Vector3d inv_inertia;
  BodyState s0;
  double t0 = 0, mass = 1;
  mutable long evals = 0;

  FreeSystem(const RigidBodyModel& m, const BodyState& s, double t) : inv_inertia(m.inv_inertia), s0(s), t0(t), mass(m.mass) {}
  Vec<N> pack(const BodyState& s) const {
    Vec<N> y;
    y << s.q.coeffs(), momentum_body(s);
    return y;
  }
  /// q' = ½ q ⊗ (0, ω), Π' = Π × ω, ω = I⁻¹Π (body_rate in scalars).
  void rate(double /*t*/, const Vec<N>& y, Vec<N>& d) const {
    ++evals;
    const double wx = inv_inertia.x() * y[4], wy = inv_inertia.y() * y[5], wz = inv_inertia.z() * y[6];
    d[0] = 0.5 * (y[3] * wx + (y[1] * wz - y[2] * wy));
    d[1] = 0.5 * (y[3] * wy + (y[2] * wx - y[0] * wz));
    d[2] = 0.5 * (y[3] * wz + (y[0] * wy - y[1] * wx));
    d[3] = -0.5 * ((y[0] * wx + y[1] * wy) + y[2] * wz);
    d[4] = y[5] * wz - y[6] * wy;
    d[5] = y[6] * wx - y[4] * wz;
    d[6] = y[4] * wy - y[5] * wx;
  }
  /// f(y + Δ) − f(y) without forming y + Δ: f is bilinear in (q, Π), so the
  /// difference is Π × W + ΔΠ × (ω + W) and ½ (q ⊗ W + Δq ⊗ (ω + W)), W = I⁻¹ΔΠ.
  /// Its round-off scales with Δ rather than with the state (what lets
  /// dop853's large stage weights, Σ|b| ≈ 13, keep the T-handle's flips).
  void rate_delta(double /*t*/, const Vec<N>& y, const Vec<N>& /*f*/, const Vec<N>& dl, Vec<N>& g) const {
    ++evals;
    const Eigen::Vector3d pi = y.segment<3>(4), dpi = dl.segment<3>(4);
    const Eigen::Vector3d w = inv_inertia.cwiseProduct(pi), W = inv_inertia.cwiseProduct(dpi), wW = w + W;
    g.segment<3>(4) = pi.cross(W) + dpi.cross(wW);
    const Eigen::Vector3d u = y.head<3>(), du = dl.head<3>();
    const double qw = y[3], dw = dl[3];
    g.head<3>() = 0.5 * ((qw * W + u.cross(W)) + (dw * wW + du.cross(wW)));
    g[3] = -0.5 * (u.dot(W) + du.dot(wW));
  }
  BodyState state(const Vec<N>& y, double t) const {
    BodyCoords x;
    x.q.coeffs() = y.head<4>();
    x.pi = y.segment<3>(4);
    x.P = s0.P;
    x.c = s0.c + (t - t0) * s0.P / mass;
    return state_of(x);
  }
};

/// Forces act: (q, Π, c, P) through body_rate, the ODE every method shares.
struct ForcedSystem {
  static constexpr int N = 13;
  const RigidBodyModel* m;
  mutable long evals = 0;

  static BodyCoords coords(const Vec<N>& y) {
    BodyCoords x;
    x.q.coeffs() = y.head<4>();
    x.pi = y.segment<3>(4);
    x.c = y.segment<3>(7);
    x.P = y.segment<3>(10);
    return x;
  }
  Vec<N> pack(const BodyState& s) const {
    Vec<N> y;
    y << s.q.coeffs(), momentum_body(s), s.c, s.P;
    return y;
  }
  void rate(double t, const Vec<N>& y, Vec<N>& d) const {
    ++evals;
    const BodyRate r = body_rate(*m, coords(y), t);
    d << r.dq, r.dpi, r.dc, r.dP;
  }
  void rate_delta(double t, const Vec<N>& y, const Vec<N>& f, const Vec<N>& dl, Vec<N>& g) const {
    rate(t, y + dl, g);
    g -= f;
  }
  BodyState state(const Vec<N>& y, double /*t*/) const { return state_of(coords(y)); }
};

/// Step control shared by the pairs. `Pair` provides the stages, the error
/// estimate and the dense output (rk45.cpp, dop853.cpp).
template <class Pair, class Sys>
class Engine final : public AdaptiveIntegrator {
  static constexpr int N = Sys::N;
  using V = Vec<N>;

 public:
  Engine(const Sys& sys, const Scales& sc, const BodyState& s0, double t0, const AdaptiveOptions& o)
      : sys_(sys), sc_(sc), opt_(o), t_(t0), t_prev_(t0), y_(sys.pack(s0)), y_prev_(y_) {
    opt_.rtol /= Pair::kGlobalPerLocal;
    opt_.atol /= Pair::kGlobalPerLocal;
    lost_.setZero();
    sys_.rate(t_, y_, kbuf_[0][0]);
    h_ = initial_step();
  }
  BodyState advance_to(double t) override {
    while (t_ < t) take_step();
    if (t == t_) return sys_.state(y_, t_);
    if (!dense_ready_) {
      Pair::dense(sys_, t_prev_, y_prev_, y_, t_ - t_prev_, kbuf_[cur_ ^ 1], dense_);
      dense_ready_ = true;
    }
    return sys_.state(Pair::interpolate(dense_, y_prev_, (t - t_prev_) / (t_ - t_prev_)), t);
  }
  long accepted() const override { return accepted_; }
  long rejected() const override { return rejected_; }
  long evaluations() const override { return sys_.evals; }
  double time() const override { return t_; }
  double next_step() const override { return h_; }

 private:
  double norm(const V& v) const { return group_error<N>(v, y_, y_, sc_, opt_); }

  // HNW I §II.4, p. 169: h from ‖y‖/‖f‖ and one explicit Euler probe.
  double initial_step() const {
    const V& k0 = kbuf_[cur_][0];
    const double d0 = norm(y_), d1 = norm(k0);
    const double h0 = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
    V f1;
    sys_.rate(t_ + h0, y_ + h0 * k0, f1);
    const double d2 = norm(f1 - k0) / h0, dm = std::max(d1, d2);
    const double h1 = dm <= 1e-15 ? std::max(1e-6, h0 * 1e-3) : std::pow(0.01 / dm, Pair::kExpo);
    return std::min({100 * h0, h1, opt_.h_max});
  }

  void take_step() {
    constexpr double kSafe = 0.9, kBeta = 0.04, kExpo1 = Pair::kExpo - 0.75 * kBeta;
    bool rejected = false;
    for (;;) {
      if (accepted_ + rejected_ >= opt_.max_steps)
        throw Diverged(std::string(Pair::kName) + " exceeded " + std::to_string(opt_.max_steps) +
                           " steps (tolerance too tight?)", t_, accepted_);
      // The step ends on t_stop rather than past it (1e-12: no sliver step after).
      const double left = opt_.t_stop - t_;
      const double h = h_ >= left * (1 - 1e-12) ? left : h_;
      std::array<V, Pair::kSlots>& k = kbuf_[cur_];
      V dy, y1;
      Pair::stages(sys_, t_, y_, h, k, dy);
      // Compensated sum (Kahan; HLW GNI §VIII.5): y1 = y + (dy − lost).
      const V d = dy - lost_;
      y1 = y_ + d;
      sys_.rate(t_ + h, y1, k[Pair::kFsal]);
      const double err = Pair::error(k, h, y_, y1, sc_, opt_);
      if (!std::isfinite(err)) throw Diverged(std::string(Pair::kName) + " produced a non-finite state", t_, accepted_);
      // One log per step: err^expo1 and err_old^β as exponentials of logs
      // (with the squared norm, about 6 % of a torque-free step; adaptive_study.sh).
      const double log_err = std::log(err);
      if (err <= 1.0) {
        // PI controller (Hairer's DOPRI5/DOP853: fac = err^expo1 / err_old^β).
        const double fac = std::clamp(std::exp(kExpo1 * log_err - kBeta * log_err_old_) / kSafe, 1 / Pair::kFacMax,
                                      1 / Pair::kFacMin);
        double h_new = std::min(h / fac, opt_.h_max);
        if (rejected) h_new = std::min(h_new, h);
        log_err_old_ = std::max(log_err, kLogErrFloor);
        lost_ = (y1 - y_) - d;
        t_prev_ = t_;
        y_prev_ = y_;
        t_ = t_ + h;
        if (h == left) t_ = opt_.t_stop;
        y_ = y1;
        // This step's stages stay for its dense output; the next step's k1 is its FSAL stage.
        kbuf_[cur_ ^ 1][0] = k[Pair::kFsal];
        cur_ ^= 1;
        dense_ready_ = false;
        ++accepted_;
        // Keep the controller's step: a step cut to t_stop is not a new estimate.
        h_ = h == left && h < h_ ? h_ : h_new;
        return;
      }
      ++rejected_;
      rejected = true;
      h_ = h / std::min(1 / Pair::kFacMin, std::exp(kExpo1 * log_err) / kSafe);
    }
  }

  Sys sys_;
  Scales sc_;
  AdaptiveOptions opt_;
  static constexpr double kLogErrFloor = -9.210340371976184;  // log(1e-4): Hairer's floor on err_old
  double t_, t_prev_, h_ = 0, log_err_old_ = kLogErrFloor;
  V y_, y_prev_, lost_;
  std::array<V, Pair::kSlots> kbuf_[2];  // stages of the step being taken ([cur_]) and of the last one
  int cur_ = 0;
  std::array<V, Pair::kDense> dense_;
  bool dense_ready_ = false;
  long accepted_ = 0, rejected_ = 0;
};

template <class Pair>
std::unique_ptr<AdaptiveIntegrator> make(const RigidBodyModel& m, const BodyState& s0, double t0,
                                         const AdaptiveOptions& o) {
  const Scales sc(m, s0);
  if (m.forces.empty()) return std::make_unique<Engine<Pair, FreeSystem>>(FreeSystem(m, s0, t0), sc, s0, t0, o);
  return std::make_unique<Engine<Pair, ForcedSystem>>(ForcedSystem{&m}, sc, s0, t0, o);
}

/// One uncontrolled step of the pair's high-order solution, on the forced system (any body).
template <class Pair>
BodyState fixed_step(const RigidBodyModel& m, const BodyState& s, double t, double h) {
  const ForcedSystem sys{&m};
  std::array<Vec<13>, Pair::kSlots> k;
  const Vec<13> y = sys.pack(s);
  sys.rate(t, y, k[0]);
  Vec<13> dy;
  Pair::stages(sys, t, y, h, k, dy);
  return sys.state(y + dy, t + h);
}

}  // namespace tumble::erk
