#include "core/rk45.hpp"

#include <algorithm>
#include <cmath>

#include "core/body_frame.hpp"
#include "core/error.hpp"

namespace tumble {

namespace {

using Vec = Rk45::Vec;

// Dormand–Prince coefficients (HNW I, Table 5.2) and dense output (HNW I, §II.6).
constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
constexpr double a21 = 1.0 / 5;
constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561, a54 = -212.0 / 729;
constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                 a65 = -5103.0 / 18656;
constexpr double a71 = 35.0 / 384, a73 = 500.0 / 1113, a74 = 125.0 / 192, a75 = -2187.0 / 6784,
                 a76 = 11.0 / 84;
constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                 e6 = 22.0 / 525, e7 = -1.0 / 40;
constexpr double d1 = -12715105075.0 / 11282082432, d3 = 87487479700.0 / 32700410799,
                 d4 = -10690763975.0 / 1880347072, d5 = 701980252875.0 / 199316789632,
                 d6 = -1453857185.0 / 822651844, d7 = 69997945.0 / 29380423;

// The integration coordinates are Euler's (c, q, P, Π), Π = q̄ L (body_frame.hpp):
// in them the error keeps off the separatrix as in rk4.
Vec pack(const BodyState& s) {
  const BodyCoords x = to_body_coords(s);
  Vec y;
  y << x.c, x.q.coeffs(), x.P, x.pi;
  return y;
}

BodyCoords coords(const Vec& y) {
  BodyCoords x;
  x.c = y.segment<3>(0);
  x.q.coeffs() = y.segment<4>(3);
  x.P = y.segment<3>(7);
  x.pi = y.segment<3>(10);
  return x;
}

/// The seed's state: q normalised, L = q Π.
BodyState unpack(const Vec& y) { return from_body_coords(coords(y)); }

// One Dormand–Prince step from (t, y) with k1 = f(t, y): stages k1..k7 and y1.
struct Stages {
  Vec k[7];
  Vec y1;
};

template <class F>
Stages dp_stages(const F& f, double t, const Vec& y, const Vec& k1, double h) {
  Stages s;
  Vec* k = s.k;
  k[0] = k1;
  k[1] = f(t + c2 * h, y + h * (a21 * k[0]));
  k[2] = f(t + c3 * h, y + h * (a31 * k[0] + a32 * k[1]));
  k[3] = f(t + c4 * h, y + h * (a41 * k[0] + a42 * k[1] + a43 * k[2]));
  k[4] = f(t + c5 * h, y + h * (a51 * k[0] + a52 * k[1] + a53 * k[2] + a54 * k[3]));
  k[5] = f(t + h, y + h * (a61 * k[0] + a62 * k[1] + a63 * k[2] + a64 * k[3] + a65 * k[4]));
  s.y1 = y + h * (a71 * k[0] + a73 * k[2] + a74 * k[3] + a75 * k[4] + a76 * k[5]);
  k[6] = f(t + h, s.y1);  // FSAL: also the next step's k1
  return s;
}

Vec rhs(const RigidBodyModel& m, double t, const Vec& y) {
  const BodyRate d = body_rate(m, coords(y), t);
  Vec out;
  out << d.dc, d.dq, d.dP, d.dpi;
  return out;
}

}  // namespace

Rk45::Rk45(const RigidBodyModel& m, const BodyState& s0, double t0, const Rk45Options& opt)
    : m_(&m), opt_(opt), t_(t0), h_(0), y_(pack(s0)), t_prev_(t0), y_prev_(y_) {
  k1_ = f(t_, y_);
  h_ = initial_step();
  dense_.setZero();
}

Vec Rk45::f(double t, const Vec& y) const { return rhs(*m_, t, y); }

// HNW I, p. 169: h from ‖y‖/‖f‖ and one explicit Euler probe.
double Rk45::initial_step() const {
  const Vec sc = opt_.atol + opt_.rtol * y_.cwiseAbs().array();
  const double d0 = std::sqrt((y_.array() / sc.array()).square().mean());
  const double d1v = std::sqrt((k1_.array() / sc.array()).square().mean());
  double h0 = (d0 < 1e-5 || d1v < 1e-5) ? 1e-6 : 0.01 * d0 / d1v;
  const Vec f1 = f(t_ + h0, y_ + h0 * k1_);
  const double d2 = std::sqrt(((f1 - k1_).array() / sc.array()).square().mean()) / h0;
  const double h1 = std::max(d1v, d2) <= 1e-15 ? std::max(1e-6, h0 * 1e-3)
                                                : std::pow(0.01 / std::max(d1v, d2), 1.0 / 5);
  return std::min({100 * h0, h1, opt_.h_max});
}

void Rk45::take_step() {
  for (;;) {
    if (accepted_ + rejected_ >= opt_.max_steps)
      throw Diverged("rk45 exceeded " + std::to_string(opt_.max_steps) + " steps (tolerance too tight?)", t_,
                     accepted_);
    const double h = h_;
    const Stages st = dp_stages([this](double tt, const Vec& y) { return f(tt, y); }, t_, y_, k1_, h);
    const Vec &k1 = st.k[0], &k3 = st.k[2], &k4 = st.k[3], &k5 = st.k[4], &k6 = st.k[5], &k7 = st.k[6];
    const Vec& y1 = st.y1;
    const Vec err = h * (e1 * k1 + e3 * k3 + e4 * k4 + e5 * k5 + e6 * k6 + e7 * k7);
    const Vec sc = opt_.atol + opt_.rtol * y_.cwiseAbs().cwiseMax(y1.cwiseAbs()).array();
    const double en = std::sqrt((err.array() / sc.array()).square().mean());
    if (!std::isfinite(en)) throw Diverged("rk45 produced a non-finite state", t_, accepted_);
    // Standard controller with safety 0.9, growth limited to [0.2, 5] (HNW I, II.4).
    const double fac = std::clamp(0.9 * std::pow(std::max(en, 1e-10), -0.2), 0.2, 5.0);
    if (en <= 1.0) {
      // Dense output coefficients (HNW's CONTD5): y(t+θh) as a quartic in θ.
      const Vec ydiff = y1 - y_;
      const Vec bspl = h * k1 - ydiff;
      dense_.col(0) = y_;
      dense_.col(1) = ydiff;
      dense_.col(2) = bspl;
      dense_.col(3) = ydiff - h * k7 - bspl;
      dense_.col(4) = h * (d1 * k1 + d3 * k3 + d4 * k4 + d5 * k5 + d6 * k6 + d7 * k7);
      t_prev_ = t_;
      y_prev_ = y_;
      t_ += h;
      y_ = y1;
      y_.segment<4>(3).normalize();  // seed erratum 5: stay on the unit sphere
      k1_ = f(t_, y_);
      ++accepted_;
      h_ = std::min(h * fac, opt_.h_max);
      return;
    }
    ++rejected_;
    h_ = h * std::min(1.0, fac);
  }
}

BodyState Rk45::advance_to(double t) {
  while (t_ < t) take_step();
  if (t == t_) return unpack(y_);
  const double theta = (t - t_prev_) / (t_ - t_prev_), th1 = 1 - theta;
  const Vec y = dense_.col(0) +
                theta * (dense_.col(1) + th1 * (dense_.col(2) + theta * (dense_.col(3) + th1 * dense_.col(4))));
  return unpack(y);
}

BodyState rk45_fixed_step(const RigidBodyModel& m, const BodyState& s, double t, double h) {
  // One uncontrolled 5th-order Dormand–Prince step (for convergence studies).
  const auto F = [&m](double tt, const Vec& y) { return rhs(m, tt, y); };
  const Vec y = pack(s);
  return unpack(dp_stages(F, t, y, F(t, y), h).y1);
}

}  // namespace tumble
