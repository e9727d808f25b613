#include "core/methods/explicit_rk.hpp"

#include <array>

namespace tumble {

const ButcherTableau kEulerTableau{1, {{{0}}}, {1}, {0}};

const ButcherTableau kRk4Tableau{
    4,
    {{{0}, {0.5}, {0, 0.5}, {0, 0, 1}}},
    {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6},
    {0, 0.5, 0.5, 1}};

namespace {

template <class F>
BodyState rk_step(const ButcherTableau& tab, F&& f, const RigidBodyModel& m, const BodyState& s,
                  double t, double h) {
  std::array<Derivative, 7> k;
  for (int i = 0; i < tab.stages; ++i) {
    BodyState xi = s;
    for (int j = 0; j < i; ++j)
      if (tab.a[i][j] != 0) xi = add_scaled(xi, h * tab.a[i][j], k[j]);
    k[i] = f(m, xi, t + tab.c[i] * h);
  }
  BodyState out = s;
  for (int i = 0; i < tab.stages; ++i) out = add_scaled(out, h * tab.b[i], k[i]);
  out.q.normalize();
  return out;
}

// The same stages as rk_step on kRk4Tableau, unrolled: identical operations in
// the same order (h·0.5, h·1, h·(1/6), h·(1/3)), so the same bits.
template <class F>
BodyState rk4_unrolled(F&& f, const RigidBodyModel& m, const BodyState& s, double t, double h) {
  const double ha = h * 0.5, b1 = h * (1.0 / 6), b2 = h * (1.0 / 3);
  const Derivative k1 = f(m, s, t);
  const Derivative k2 = f(m, add_scaled(s, ha, k1), t + 0.5 * h);
  const Derivative k3 = f(m, add_scaled(s, ha, k2), t + 0.5 * h);
  const Derivative k4 = f(m, add_scaled(s, h, k3), t + h);
  BodyState out = add_scaled(add_scaled(add_scaled(add_scaled(s, b1, k1), b2, k2), b2, k3), b1, k4);
  out.q.normalize();
  return out;
}

// Torque-free: P and L are constant and c' = P/M, so only q varies between
// stages. c takes the same four increments as in rk_step; P, L are not touched.
// In scalars (no packed Eigen temporaries to unpack on the stage chain), same
// operations in the same order as rk_step, so the same bits.
using Q4 = std::array<double, 4>;  // (x, y, z, w)

[[gnu::always_inline]] inline Q4 rate4(const RigidBodyModel& m, const Q4& q, const Eigen::Vector3d& L) {
  const QuatRate r = quaternion_rate(m.inv_inertia, q[0], q[1], q[2], q[3], L);
  return {r.x, r.y, r.z, r.w};
}

[[gnu::always_inline]] inline Q4 axpy4(const Q4& a, double t, const Q4& k) {
  return {a[0] + t * k[0], a[1] + t * k[1], a[2] + t * k[2], a[3] + t * k[3]};
}

BodyState rk4_free(const RigidBodyModel& m, const BodyState& s, double h) {
  const double ha = h * 0.5, b1 = h * (1.0 / 6), b2 = h * (1.0 / 3);
  const Eigen::Vector3d v = s.P / m.mass;
  const Q4 q0{s.q.x(), s.q.y(), s.q.z(), s.q.w()};
  const Q4 k1 = rate4(m, q0, s.L);
  const Q4 k2 = rate4(m, axpy4(q0, ha, k1), s.L);
  const Q4 k3 = rate4(m, axpy4(q0, ha, k2), s.L);
  const Q4 k4 = rate4(m, axpy4(q0, h, k3), s.L);
  const Q4 q = axpy4(axpy4(axpy4(axpy4(q0, b1, k1), b2, k2), b2, k3), b1, k4);
  BodyState out = s;
  out.c = (((s.c + b1 * v) + b2 * v) + b2 * v) + b1 * v;
  out.q = Eigen::Quaterniond(q[3], q[0], q[1], q[2]);
  out.q.normalize();
  return out;
}

}  // namespace

BodyState rk4_step(const RigidBodyModel& m, const BodyState& s, double t, double h) {
  if (m.forces.empty()) return rk4_free(m, s, h);
  return rk4_unrolled(derivative, m, s, t, h);
}

BodyState euler_step(const RigidBodyModel& m, const BodyState& s, double t, double h) {
  if (!m.forces.empty()) return rk_step(kEulerTableau, derivative, m, s, t, h);
  BodyState out = s;
  out.c = s.c + h * (s.P / m.mass);
  out.q.coeffs() = s.q.coeffs() + h * quaternion_rate(m, s.q, s.L);
  out.q.normalize();
  return out;
}

BodyState explicit_rk_step(const ButcherTableau& tab, const RigidBodyModel& m, const BodyState& s,
                           double t, double h) {
  return rk_step(tab, derivative, m, s, t, h);
}

BodyState explicit_rk_step(const ButcherTableau& tab, const DerivativeFn& f, const RigidBodyModel& m,
                           const BodyState& s, double t, double h) {
  return rk_step(tab, f, m, s, t, h);
}

}  // namespace tumble
