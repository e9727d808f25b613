// Boost.odeint peer (header-only, ships with libboost-dev): textbook RK4 and
// Dormand–Prince 5(4) on a torque-free body, in two formulations.
//  - world: state (q, L_world), q' = ½ ω_world ⊗ q̂ with q̂ = q/|q| taken inside
//    f (the seed's ODE, the rotation evaluated on the unit sphere);
//  - body: state (q, Π = Rᵀ L), Euler's equations Π' = Π × ω_body and
//    q' = ½ q ⊗ ω_body, ω_body = J⁻¹ Π (Hairer, Lubich & Wanner, GNI §VII.5).
// Both have the same exact flow; only the integration coordinates differ.
#include <array>
#include <cmath>
#include <type_traits>

#include <boost/numeric/odeint.hpp>

#include "bench/peers.hpp"
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

// Error-controlled Dormand–Prince (odeint's default controller: error
// ≤ atol + rtol·|x|, componentwise max), ending exactly at T.
BodyState run_dopri5_body(const RigidBodyModel& m, const BodyState& s0, double T, double rtol) {
  State x = to_state<BodyRhs>(s0);
  auto stepper = odeint::make_controlled(rtol, rtol, odeint::runge_kutta_dopri5<State>());
  odeint::integrate_adaptive(stepper, BodyRhs{m.inv_inertia}, x, 0.0, T, 1e-3);
  return from_state<BodyRhs>(x, m, s0, T);
}

template <class Rhs, class Algorithm>
MakeStepper maker() {
  return [](const RigidBodyModel& m, const BodyState& s0) -> std::unique_ptr<Stepper> {
    return std::make_unique<OdeintStepper<Rhs, Algorithm>>(m, s0);
  };
}

}  // namespace

std::vector<PeerConfig> odeint_configs() {
  using Rk4 = odeint::runge_kutta4<State>;
  using Dopri5 = odeint::runge_kutta_dopri5<State>;
  return {
      {"odeint_rk4_world", "dt", run_fixed_odeint<WorldRhs, Rk4>, maker<WorldRhs, Rk4>()},
      {"odeint_rk4_body", "dt", run_fixed_odeint<BodyRhs, Rk4>, maker<BodyRhs, Rk4>()},
      {"odeint_dopri5_body", "rtol", run_dopri5_body, maker<BodyRhs, Dopri5>()},
  };
}

}  // namespace tumble::bench
