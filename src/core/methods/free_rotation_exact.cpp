#include "core/methods/free_rotation_exact.hpp"

#include <cmath>
#include <limits>
#include <utility>

#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/special_functions/ellint_rj.hpp>

#include "core/methods/jacobi_elliptic.hpp"
#include "core/quaternion.hpp"
#include "core/methods/rotation_steps.hpp"

namespace tumble {

namespace {

constexpr double kSymmetricTol = 1e-13;  // relative moment difference treated as equal

// Carlson's R_F, R_J evaluated in double: Boost's default promotes to long double,
// ~1 µs per R_J (3 per step) against ~0.1 µs, for ≤ 6 ulp instead of 1 over the
// arguments used here with k'² ≥ 1e-12, ≤ 50 ulp closer to the separatrix
// (checked against 50-digit arithmetic).
using DoubleEval = boost::math::policies::policy<boost::math::policies::promote_double<false>>;

// k'² = 1 - k² for the modulus k as stored, formed as (1 - k)(1 + k) so it keeps
// full relative precision as k → 1 (near the separatrix), where 1 - k² sin²φ
// would cancel. sn/cn/dn get k' = √(this) too, so K, F, G and sn/cn/dn all
// refer to one modulus.
double complementary(double k) { return (1 - k) * (1 + k); }

// F(φ, k) = s R_F(c², c² + k'² s², 1) for s = sin φ, c = cos φ ≥ 0 (DLMF 19.25.5),
// with 1 - k² s² written as c² + k'² s² (no cancellation).
double ellint_f_sc(double kc2, double s, double c) {
  return s * boost::math::ellint_rf(c * c, c * c + kc2 * s * s, 1.0, DoubleEval());
}

// Incomplete F(φ, k) for any φ in (-π, π] given (sin φ, cos φ), by symmetry from [0, π/2].
double ellint_f_any(double kc2, double s, double c, double K) {
  if (c >= 0) return ellint_f_sc(kc2, s, c);
  return std::copysign(2 * K - ellint_f_sc(kc2, std::abs(s), -c), s);
}

// ∫₀^φ sin²θ / ((1 + ν sin²θ) √(1 - k² sin²θ)) dθ for |φ| ≤ π/2 (s = sin φ, c = cos φ ≥ 0):
// (Π(-ν; φ) - F(φ))/(-ν) written with Carlson's R_J (DLMF 19.25.14) so there is no
// cancellation at small ν, and with 1 - k² s² = c² + k'² s² so there is none as k → 1.
double g_reduced(double kc2, double nu, double s, double c) {
  if (s == 0) return 0;
  const double s2 = s * s;
  return s * s2 / 3.0 * boost::math::ellint_rj(c * c, c * c + kc2 * s2, 1.0, 1 + nu * s2, DoubleEval());
}

// (cos α/2, sin α/2) for α = atan2(y, x) ∈ (-π, π], from the half-angle formulas
// cos²(α/2) = (1 + cos α)/2, sin α = 2 sin(α/2) cos(α/2), taking the root that
// does not cancel: no atan2, sin, cos. y = x = 0 does not occur here (l > 0, sn² + cn² = 1).
std::pair<double, double> half_angle(double y, double x) {
  const double r = std::sqrt(x * x + y * y);
  if (x >= 0) {
    const double c = std::sqrt(0.5 + 0.5 * (x / r));
    return {c, y / (2 * r * c)};
  }
  const double sh = std::sqrt(0.5 - 0.5 * (x / r));
  return {std::abs(y) / (2 * r * sh), std::copysign(sh, y)};
}

}  // namespace

bool closed_form_is_trigonometric(const Eigen::Vector3d& inertia) {
  const double I1 = inertia[0], I2 = inertia[1], I3 = inertia[2];
  return I2 - I1 <= kSymmetricTol * I3 || I3 - I2 <= kSymmetricTol * I3;
}

FreeRotationExact::FreeRotationExact(const Eigen::Vector3d& inertia, const Eigen::Quaterniond& q0,
                                     const Eigen::Vector3d& L)
    : inertia_(inertia), q0_(q0.normalized()), L_(L), l_(L.norm()) {
  const double I1 = inertia[0], I2 = inertia[1], I3 = inertia[2];
  const Eigen::Vector3d pi = q0_.conjugate() * L_;
  if (l_ == 0) {
    kind_ = Kind::at_rest;
    return;
  }
  if (I3 - I1 <= kSymmetricTol * I3) {
    kind_ = Kind::spherical;
    i_perp_ = inertia.mean();
    return;
  }
  if (I2 - I1 <= kSymmetricTol * I3 || I3 - I2 <= kSymmetricTol * I3) {
    kind_ = Kind::symmetric;
    axis_ = I2 - I1 <= kSymmetricTol * I3 ? 2 : 0;
    i_perp_ = axis_ == 2 ? 0.5 * (I1 + I2) : 0.5 * (I2 + I3);
    lambda_ = pi[axis_] * (1.0 / inertia[axis_] - 1.0 / i_perp_);
    return;
  }
  kind_ = Kind::asymmetric;
  init_asymmetric(pi);
}

void FreeRotationExact::init_asymmetric(const Eigen::Vector3d& pi) {
  const double I1 = inertia_[0], I2 = inertia_[1], I3 = inertia_[2];
  // l² - 2E·I2 without cancellation decides which axis Π circulates about.
  const double d = pi[0] * pi[0] * (I1 - I2) / I1 + pi[2] * pi[2] * (I3 - I2) / I3;
  const bool major = d >= 0;
  // Primed frame: identity, or the proper permutation v' = (v3, -v2, v1)
  // (a half turn about (1, 0, 1)/√2).
  q_perm_ = major ? Eigen::Quaterniond::Identity()
                  : Eigen::Quaterniond(0, std::sqrt(0.5), 0, std::sqrt(0.5));
  const Eigen::Vector3d p = q_perm_ * pi;  // Π' (rotation of components)
  if (major) {
    J1_ = I1; J2_ = I2; J3_ = I3;
  } else {
    J1_ = I3; J2_ = I2; J3_ = I1;
  }
  // Squared amplitudes from sums of same-signed terms (no cancellation).
  const double x1 = p[0] * p[0] * (J3_ - J1_) / J1_ + p[1] * p[1] * (J3_ - J2_) / J2_;  // 2E J3 - l²
  const double x3 = p[1] * p[1] * (J2_ - J1_) / J2_ + p[2] * p[2] * (J3_ - J1_) / J3_;  // l² - 2E J1
  A1_ = std::sqrt(std::max(0.0, x1 / (J1_ * (J3_ - J1_))));
  A2_ = std::sqrt(std::max(0.0, x1 / (J2_ * (J3_ - J2_))));
  A3_ = std::sqrt(std::max(0.0, x3 / (J3_ * (J3_ - J1_))));
  rho_ = std::sqrt(J1_ * (J3_ - J1_) / (J2_ * (J3_ - J2_)));
  wp_ = std::sqrt((J3_ - J2_) * x3 / (J1_ * J2_ * J3_));
  double k2 = (J2_ - J1_) * x1 / ((J3_ - J2_) * x3);
  k2 = std::clamp(k2, 0.0, 1.0);
  k_ = std::sqrt(k2);
  periodic_ = k_ < 1.0;  // k2 just below 1 can round to k = 1, where K is infinite
  const double kc2 = complementary(k_);
  kc_ = std::sqrt(kc2);
  K_ = periodic_ ? boost::math::ellint_rf(0.0, kc2, 1.0, DoubleEval()) : std::numeric_limits<double>::infinity();
  mu_ = (J2_ - J1_) / (J3_ - J2_);
  nu_ = mu_ * J3_ / J1_;
  init_phase(p);
}

void FreeRotationExact::init_phase(const Eigen::Vector3d& p) {
  const double kc2 = complementary(k_);
  // Signs: Π'3 never changes sign (dn > 0); Euler's equations then fix s2.
  const double sigma = J3_ > J1_ ? 1.0 : -1.0;
  s3_ = p[2] < 0 ? -1.0 : 1.0;
  s2_ = sigma * s3_;
  // Phase: (sn τ0, cn τ0) with the amplitudes divided out; τ0 = F(am τ0).
  const double sn_a = p[1] / (J2_ * s2_ * rho_), cn_a = p[0] / J1_, r0 = std::hypot(sn_a, cn_a);
  const double sn0 = r0 > 0 ? sn_a / r0 : 0.0, cn0 = r0 > 0 ? cn_a / r0 : 1.0;
  tau0_ = periodic_ ? ellint_f_any(kc2, sn0, cn0, K_) : std::atanh(sn0);
  G_K_ = periodic_ ? g_reduced(kc2, nu_, 1.0, 0.0) : 0;
  // sn, cn at τ0 are (sn0, cn0) by construction, so no Jacobi evaluation; G(τ0)
  // as phase() reduces it: τ0 = ±(2K - F) when cn0 < 0, and G(2K) = 2 G(K).
  Phase ph0;
  if (periodic_) {
    ph0 = {sn0, cn0, std::sqrt(cn0 * cn0 + kc2 * sn0 * sn0),
           cn0 >= 0 ? g_reduced(kc2, nu_, sn0, cn0)
                    : std::copysign(2 * G_K_, sn0) + g_reduced(kc2, nu_, -sn0, -cn0)};
  } else {
    ph0 = phase(tau0_);
  }
  G_tau0_ = ph0.g;
  // world ← L-frame at φ = 0: R0 = R_frame · B(τ0)·P.
  q_frame0_ = q0_ * body_from_elliptic(ph0).conjugate();
}

// sn, cn, dn at τ (one Jacobi evaluation, argument reduced by the period 4K),
// plus G(τ) = ∫₀^τ sn²/(1 + ν sn²) du, reduced by the period 2K of sn².
FreeRotationExact::Phase FreeRotationExact::phase(double tau) const {
  Phase ph;
  if (!periodic_) {
    ph.sn = std::tanh(tau);
    ph.cn = ph.dn = 1.0 / std::cosh(tau);
    // On the separatrix (k = 1) G has a closed form, G(τ) = τ/(1+ν) - atan(√ν tanh τ)/((1+ν)√ν).
    // Only its bounded part is kept here; orientation() adds ωp t/(1+ν), so that
    // τ0 = ±∞ (a spin exactly about the intermediate axis) gives ΔG = ωp t/(1+ν).
    const double rn = std::sqrt(nu_);
    ph.g = -std::atan(rn * ph.sn) / ((1 + nu_) * rn);
    return ph;
  }
  const double m4 = std::round(tau / (4 * K_));
  const double r = tau - 4 * K_ * m4;  // in [-2K, 2K]
  const JacobiSnCnDn j = jacobi_sn_cn_dn(r, k_, kc_);
  ph.sn = j.sn;
  ph.cn = j.cn;
  ph.dn = j.dn;
  // Shift r into [-K, K] by ±2K, where sn and cn change sign.
  double m2 = 2 * m4, sn2 = ph.sn, cn2 = ph.cn;
  if (r > K_ || r < -K_) {
    m2 += r > 0 ? 1 : -1;
    sn2 = -sn2;
    cn2 = -cn2;
  }
  ph.g = 2 * m2 * G_K_ + g_reduced(complementary(k_), nu_, sn2, cn2);
  return ph;
}

Eigen::Vector3d FreeRotationExact::primed_momentum(const Phase& ph) const {
  return {J1_ * A1_ * ph.cn, J2_ * A2_ * s2_ * ph.sn, J3_ * A3_ * s3_ * ph.dn};
}

// qB ⊗ qP, where B = Rx(θ) Rz(ψ) takes the body direction of L to the L-frame's z:
// Π'/l = (sinθ sinψ, sinθ cosψ, cosθ). ψ uses the amplitude-free ratio so that
// it stays defined for a pure spin about axis 3'.
Eigen::Quaterniond FreeRotationExact::body_from_elliptic(const Phase& ph) const {
  const Eigen::Vector3d p = primed_momentum(ph);
  const auto [ct, st] = half_angle(std::hypot(p[0], p[1]), p[2]);
  const auto [cp, sp] = half_angle(J1_ * ph.cn, J2_ * s2_ * rho_ * ph.sn);
  const Eigen::Quaterniond qb(ct * cp, st * cp, -st * sp, ct * sp);  // Rx(θ) ⊗ Rz(ψ)
  return qb * q_perm_;
}

Eigen::Quaterniond FreeRotationExact::orientation(double t) const {
  switch (kind_) {
    case Kind::at_rest:
      return q0_;
    case Kind::spherical:
      return (quat_exp(t / i_perp_ * L_) * q0_).normalized();
    case Kind::symmetric:
      return (quat_exp(t / i_perp_ * L_) * q0_ * axis_rotation(axis_, lambda_ * t)).normalized();
    case Kind::asymmetric:
      break;
  }
  const Phase ph = phase(wp_ * t + tau0_);
  // φ' = (l/J1)(1 + μ sn²)/(1 + ν sn²) integrates to (l/J1)(t + (μ - ν)/ωp ΔG).
  const double dG = ph.g - G_tau0_ + (periodic_ ? 0.0 : wp_ * t / (1 + nu_));
  const double dphi = t == 0.0 ? 0.0 : (l_ / J1_) * (t + (mu_ - nu_) / wp_ * dG);
  // R(t) = R_L Rz(φ) B(τ) P, with R_L Rz(φ0) = R0 (B(τ0) P)ᵀ: L̂ is the L-frame's z in world.
  const Eigen::Quaterniond qz = quat_exp(dphi / l_ * L_);  // world rotation about L by Δφ
  return (qz * q_frame0_ * body_from_elliptic(ph)).normalized();
}

Eigen::Vector3d FreeRotationExact::momentum_body(double t) const {
  if (kind_ != Kind::asymmetric) return orientation(t).conjugate() * L_;
  return q_perm_.conjugate() * primed_momentum(phase(wp_ * t + tau0_));
}

double FreeRotationExact::body_period() const {
  if (kind_ != Kind::asymmetric || !periodic_) return std::numeric_limits<double>::infinity();
  return 4 * K_ / wp_;
}

BodyState exact_free_state(const RigidBodyModel& m, const BodyState& s0, double t) {
  BodyState s = s0;
  s.c = s0.c + t * s0.P / m.mass;
  s.q = FreeRotationExact(m.inertia, s0.q, s0.L).orientation(t);
  return s;
}

namespace {
void free_rotation_exact(const RigidBodyModel& m, const Eigen::Vector3d& L, Eigen::Quaterniond& q, double h) {
  q = FreeRotationExact(m.inertia, q, L).orientation(h);
}
}  // namespace

BodyState exact_step(const RigidBodyModel& m, const BodyState& s, double t, double h) {
  return strang_step(m, s, t, h, free_rotation_exact);
}

}  // namespace tumble
