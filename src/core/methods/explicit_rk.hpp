// Explicit Runge–Kutta on the seed's ODE, with Butcher tableaux as data.
#pragma once

#include <array>
#include <functional>

#include "core/body.hpp"
#include "core/dynamics.hpp"

namespace tumble {

/// An explicit tableau with at most 7 stages (lower-triangular a, weights b, nodes c).
struct ButcherTableau {
  int stages;
  std::array<std::array<double, 7>, 7> a;
  std::array<double, 7> b;
  std::array<double, 7> c;
};

/// Forward Euler: 0 | 1.
extern const ButcherTableau kEulerTableau;
/// Kutta's classical 4th-order method (Hairer–Nørsett–Wanner I, Table 1.2).
extern const ButcherTableau kRk4Tableau;

/// Any function with the signature of `derivative` (tests pass the seed's
/// uncorrected form to show erratum 1).
using DerivativeFn = std::function<Derivative(const RigidBodyModel&, const BodyState&, double)>;

/// x + h Σ bᵢ kᵢ; states are combined as plain vectors (c, q, P, L), then q is
/// renormalised (seed erratum 5).
BodyState explicit_rk_step(const ButcherTableau& tab, const RigidBodyModel& m, const BodyState& s,
                           double t, double h);
BodyState explicit_rk_step(const ButcherTableau& tab, const DerivativeFn& f, const RigidBodyModel& m,
                           const BodyState& s, double t, double h);

/// `explicit_rk_step` on kRk4Tableau / kEulerTableau, specialised (unrolled
/// stages; torque-free bodies advance only q through the stages). Same bits as
/// the tableau form up to the sign of zero momenta.
BodyState rk4_step(const RigidBodyModel& m, const BodyState& s, double t, double h);
BodyState euler_step(const RigidBodyModel& m, const BodyState& s, double t, double h);

/// s + h·d (no renormalisation): the building block of the RK stages.
inline BodyState add_scaled(const BodyState& s, double h, const Derivative& d) {
  BodyState o;
  o.c = s.c + h * d.dc;
  o.q.coeffs() = s.q.coeffs() + h * d.dq;
  o.P = s.P + h * d.dP;
  o.L = s.L + h * d.dL;
  return o;
}

}  // namespace tumble
