#include "core/explicit_rk.hpp"

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

}  // namespace

BodyState explicit_rk_step(const ButcherTableau& tab, const RigidBodyModel& m, const BodyState& s,
                           double t, double h) {
  return rk_step(tab, derivative, m, s, t, h);
}

BodyState explicit_rk_step(const ButcherTableau& tab, const DerivativeFn& f, const RigidBodyModel& m,
                           const BodyState& s, double t, double h) {
  return rk_step(tab, f, m, s, t, h);
}

}  // namespace tumble
