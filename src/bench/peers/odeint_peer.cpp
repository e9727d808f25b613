// Boost.odeint peer (header-only, ships with libboost-dev): textbook RK4 and
// Dormand–Prince 5(4) on a torque-free body, in two formulations, and on a
// forced body in Euler's coordinates through tumble's own right-hand side.
//  - world: state (q, L_world), q' = ½ ω_world ⊗ q̂ with q̂ = q/|q| taken inside
//    f (the seed's ODE, the rotation evaluated on the unit sphere);
//  - body: state (q, Π = Rᵀ L), Euler's equations Π' = Π × ω_body and
//    q' = ½ q ⊗ ω_body, ω_body = J⁻¹ Π (Hairer, Lubich & Wanner, GNI §VII.5).
// Both have the same exact flow; only the integration coordinates differ.
//  - forced: state (q, Π, c, P), the derivative from core's body_rate (the
//    ODE, forces and torques every tumble method integrates).
#include <array>
#include <cmath>
#include <type_traits>

#include <boost/numeric/odeint.hpp>

#include <boost/version.hpp>

#include "bench/peers/peer.hpp"
#include "core/body_frame.hpp"
#include "core/dynamics.hpp"

namespace tumble::bench {

namespace {

namespace odeint = boost::numeric::odeint;
using State = std::array<double, 7>;  // qw, qx, qy, qz, then L_world (world) or Π (body)

struct WorldRhs {
  Eigen::Vector3d inv_inertia;  // 1/(kg·m²), principal
  void operator()(const State& x, State& dx, double /*t*/) const {
    const Eigen::Quaterniond q = Eigen::Quaterniond(x[0], x[1], x[2], x[3]).normalized();
    const Eigen::Vector3d L(x[4], x[5], x[6]);
    const Eigen::Vector3d w = q * inv_inertia.cwiseProduct(q.conjugate() * L);  // ω_world, rad/s
    const Eigen::Vector3d qv = q.vec();
    const Eigen::Vector3d dv = 0.5 * (q.w() * w + w.cross(qv));  // ½ (0, ω) ⊗ q̂
    dx = {-0.5 * w.dot(qv), dv.x(), dv.y(), dv.z(), 0, 0, 0};
  }
};

struct BodyRhs {
  Eigen::Vector3d inv_inertia;
  void operator()(const State& x, State& dx, double /*t*/) const {
    const Eigen::Vector3d pi(x[4], x[5], x[6]);
    const Eigen::Vector3d w = inv_inertia.cwiseProduct(pi);  // ω_body, rad/s
    const Eigen::Vector3d qv(x[1], x[2], x[3]);
    const Eigen::Vector3d dv = 0.5 * (x[0] * w + qv.cross(w));  // ½ q ⊗ (0, ω)
    const Eigen::Vector3d dpi = pi.cross(w);
    dx = {-0.5 * qv.dot(w), dv.x(), dv.y(), dv.z(), dpi.x(), dpi.y(), dpi.z()};
  }
};

using Forced = std::array<double, 13>;  // q (x, y, z, w), Π, c, P

struct ForcedRhs {
  const RigidBodyModel* m;
  static BodyCoords coords(const Forced& x) {
    BodyCoords b;
    b.q.coeffs() << x[0], x[1], x[2], x[3];
    b.pi = {x[4], x[5], x[6]};
    b.c = {x[7], x[8], x[9]};
    b.P = {x[10], x[11], x[12]};
    return b;
  }
  void operator()(const Forced& x, Forced& dx, double t) const {
    const BodyRate d = body_rate(*m, coords(x), t);
    dx = {d.dq[0], d.dq[1], d.dq[2], d.dq[3], d.dpi.x(), d.dpi.y(), d.dpi.z(),
          d.dc.x(), d.dc.y(), d.dc.z(), d.dP.x(), d.dP.y(), d.dP.z()};
  }
};

Forced to_forced(const BodyState& s) {
  const Eigen::Vector3d pi = momentum_body(s);
  return {s.q.x(), s.q.y(), s.q.z(), s.q.w(), pi.x(), pi.y(), pi.z(), s.c.x(), s.c.y(), s.c.z(), s.P.x(), s.P.y(), s.P.z()};
}

template <class Rhs>
constexpr bool kBody = std::is_same_v<Rhs, BodyRhs>;

template <class Rhs>
State to_state(const BodyState& s) {
  const Eigen::Vector3d v = kBody<Rhs> ? momentum_body(s) : s.L;
  return {s.q.w(), s.q.x(), s.q.y(), s.q.z(), v.x(), v.y(), v.z()};
}

template <class Rhs>
BodyState from_state(const State& x, const RigidBodyModel& m, const BodyState& s0, double t) {
  BodyState s = s0;
  s.q = Eigen::Quaterniond(x[0], x[1], x[2], x[3]).normalized();
  const Eigen::Vector3d v(x[4], x[5], x[6]);
  s.L = kBody<Rhs> ? Eigen::Vector3d(s.q * v) : v;
  s.c = s0.c + t * s0.P / m.mass;  // torque- and force-free
  return s;
}

template <class Rhs, class Algorithm>
class OdeintStepper final : public Stepper {
 public:
  OdeintStepper(const RigidBodyModel& m, const BodyState& s0) : m_(m), s0_(s0), rhs_{m.inv_inertia}, x_(to_state<Rhs>(s0)) {}
  void step(double h) override {
    stepper_.do_step(rhs_, x_, t_, h);
    t_ += h;
  }
  BodyState state() const override { return from_state<Rhs>(x_, m_, s0_, t_); }

 private:
  const RigidBodyModel& m_;
  BodyState s0_;
  Rhs rhs_;
  State x_;
  double t_ = 0;
  Algorithm stepper_;
};

// n = round(T/dt) steps of h = T/n, looped here so the timing carries no virtual call.
template <class Rhs, class Algorithm>
BodyState run_fixed_odeint(const RigidBodyModel& m, const BodyState& s0, double T, double dt) {
  const long n = std::max(1L, std::lround(T / dt));
  const double h = T / static_cast<double>(n);
  const Rhs rhs{m.inv_inertia};
  State x = to_state<Rhs>(s0);
  Algorithm stepper;
  for (long i = 0; i < n; ++i) stepper.do_step(rhs, x, static_cast<double>(i) * h, h);
  return from_state<Rhs>(x, m, s0, T);
}

// A forced body: n = round(T/dt) fixed steps on (q, Π, c, P).
template <class Algorithm>
BodyState run_fixed_forced(const RigidBodyModel& m, const BodyState& s0, double T, double dt) {
  const long n = std::max(1L, std::lround(T / dt));
  const double h = T / static_cast<double>(n);
  Forced x = to_forced(s0);
  Algorithm stepper;
  for (long i = 0; i < n; ++i) stepper.do_step(ForcedRhs{&m}, x, static_cast<double>(i) * h, h);
  return state_of(ForcedRhs::coords(x));
}

// Error-controlled Dormand–Prince (odeint's default controller: error
// ≤ atol + rtol·(|x| + h|x'|), componentwise max), ending exactly at T. Forced
// bodies on (q, Π, c, P).
BodyState run_dopri5_body(const RigidBodyModel& m, const BodyState& s0, double T, double rtol) {
  if (!m.forces.empty()) {
    Forced x = to_forced(s0);
    auto stepper = odeint::make_controlled(rtol, rtol, odeint::runge_kutta_dopri5<Forced>());
    odeint::integrate_adaptive(stepper, ForcedRhs{&m}, x, 0.0, T, 1e-3);
    return state_of(ForcedRhs::coords(x));
  }
  State x = to_state<BodyRhs>(s0);
  auto stepper = odeint::make_controlled(rtol, rtol, odeint::runge_kutta_dopri5<State>());
  odeint::integrate_adaptive(stepper, BodyRhs{m.inv_inertia}, x, 0.0, T, 1e-3);
  return from_state<BodyRhs>(x, m, s0, T);
}

// The body formulation's RK4 on any body: torque-free (q, Π) or forced (q, Π, c, P).
BodyState run_rk4_body(const RigidBodyModel& m, const BodyState& s0, double T, double dt) {
  if (!m.forces.empty()) return run_fixed_forced<odeint::runge_kutta4<Forced>>(m, s0, T, dt);
  return run_fixed_odeint<BodyRhs, odeint::runge_kutta4<State>>(m, s0, T, dt);
}

template <class Rhs, class Algorithm>
MakeStepper maker() {
  return [](const RigidBodyModel& m, const BodyState& s0) -> std::unique_ptr<Stepper> {
    return std::make_unique<OdeintStepper<Rhs, Algorithm>>(m, s0);
  };
}


}  // namespace

PeerEngine odeint_engine() {
  using Rk4 = odeint::runge_kutta4<State>;
  using Dopri5 = odeint::runge_kutta_dopri5<State>;
  return {"Boost.odeint " BOOST_LIB_VERSION " (header-only, libboost-dev)",
          "- Boost.odeint: state std::array<double, 7>, default algebra. `odeint_rk4_world`: runge_kutta4 on the seed's "
          "(q, L_world) with q normalised inside f; `odeint_rk4_body`: runge_kutta4 on (q, Π = Rᵀ L), Euler's equations "
          "Π' = Π × ω_body and q' = ½ q ⊗ ω_body; `odeint_dopri5_body`: make_controlled(atol = rtol, rtol, "
          "runge_kutta_dopri5) with integrate_adaptive on the body formulation (on the stability map and flip charts: "
          "its fixed-step Dormand–Prince step). The reported q is normalised once at the end. On forced problems "
          "`odeint_rk4_body` and `odeint_dopri5_body` integrate std::array<double, 13> (q, Π, c, P) with core's "
          "body_rate as the right-hand side: the same forces, torques and reference as tumble's methods.\n",
          {{"odeint_rk4_world", "dt", run_fixed_odeint<WorldRhs, Rk4>, maker<WorldRhs, Rk4>(), false},
           {"odeint_rk4_body", "dt", run_rk4_body, maker<BodyRhs, Rk4>(), true},
           {"odeint_dopri5_body", "rtol", run_dopri5_body, maker<BodyRhs, Dopri5>(), true}}};
}

}  // namespace tumble::bench
