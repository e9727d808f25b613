// The exact torque-free rotation of a rigid body: Jacobi elliptic functions for
// the body angular momentum, an elliptic integral of the third kind for the
// precession angle. Used by the `exact` method and as the reference in tests.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/body.hpp"

namespace tumble {

/// Closed-form solution of Ṙ = [ω_world]× R, L̇ = 0 for principal moments
/// I1 ≤ I2 ≤ I3 (kg·m²), from q(0) (world ← principal) and world L (kg·m²/s).
///
/// Derivation (Landau & Lifshitz, Mechanics §37; orientation in the spirit of
/// van Zon & Schofield, J. Comput. Phys. 225, 2007): in a frame whose axis 3'
/// is the axis Π circulates about (the major axis when |L|² ≥ 2E I2, else the
/// minor one, reached by the proper permutation (3, -2, 1)),
///   Π' = (J1 A1 cn τ, J2 A2 s2 sn τ, J3 A3 s3 dn τ),  τ = ωp t + τ0.
/// With zxz Euler angles about L, R = R_L Rz(φ) Rx(θ) Rz(ψ), where θ, ψ follow
/// from Π'/|L| and
///   φ' = (|L|/J1) (1 + μ sn²)/(1 + ν sn²),  μ = (J2-J1)/(J3-J2),  ν = μ J3/J1,
/// integrates to an elliptic integral of the third kind, evaluated through
/// Carlson's R_J (DLMF 19.25.14), which stays accurate as ν → 0.
/// Symmetric bodies use R(t) = exp(t L/I⊥) R0 exp(t λ e_a), spheres R = exp(t L/I) R0.
class FreeRotationExact {
 public:
  FreeRotationExact(const Eigen::Vector3d& inertia, const Eigen::Quaterniond& q0, const Eigen::Vector3d& L);

  /// world ← principal orientation at time t (s) after the initial state.
  Eigen::Quaterniond orientation(double t) const;
  /// Π(t), principal frame, kg·m²/s.
  Eigen::Vector3d momentum_body(double t) const;
  /// ω(t), principal frame, rad/s.
  Eigen::Vector3d omega_body(double t) const { return momentum_body(t).cwiseQuotient(inertia_); }

  enum class Kind { spherical, symmetric, asymmetric, at_rest };
  Kind kind() const { return kind_; }
  /// Period of Π(t) (s); infinite on the separatrix or for symmetric/spherical bodies at rest.
  double body_period() const;

 private:
  struct Phase {
    double sn = 0, cn = 1, dn = 1;  // Jacobi functions at τ
    double g = 0;                   // G(τ) = ∫₀^τ sn²/(1 + ν sn²) du
  };
  Phase phase(double tau) const;
  Eigen::Quaterniond body_from_elliptic(const Phase& ph) const;  // qB(τ) ⊗ qP
  void init_asymmetric(const Eigen::Vector3d& pi);  // the primed frame, amplitudes and modulus from Π
  void init_phase(const Eigen::Vector3d& p);        // signs and phase at t = 0 from Π' (after init_asymmetric)
  Eigen::Vector3d primed_momentum(const Phase& ph) const;

  Kind kind_;
  Eigen::Vector3d inertia_;
  Eigen::Quaterniond q0_;
  Eigen::Vector3d L_;
  double l_ = 0;
  // symmetric / spherical
  int axis_ = 2;
  double i_perp_ = 0, lambda_ = 0;
  // asymmetric
  Eigen::Quaterniond q_perm_;      // primed ← principal (proper permutation)
  Eigen::Quaterniond q_frame0_;    // q0 ⊗ (qB(τ0) ⊗ qP)⁻¹: world ← (L-aligned frame at φ = 0)
  double J1_ = 0, J2_ = 0, J3_ = 0, A1_ = 0, A2_ = 0, A3_ = 0, s2_ = 1, s3_ = 1;
  double rho_ = 1;                 // A2/A1, amplitude free
  double kc_ = 1;                  // k' = √((1 - k)(1 + k))
  double k_ = 0, K_ = 0, wp_ = 0, tau0_ = 0, nu_ = 0, mu_ = 0, G_K_ = 0, G_tau0_ = 0;
  bool periodic_ = true;
};

/// Whether a body with these principal moments (kg·m², ascending) has a
/// trigonometric closed form (spherical or symmetric: two moments equal),
/// rather than the elliptic one. FreeRotationExact's own test.
bool closed_form_is_trigonometric(const Eigen::Vector3d& inertia);

/// State of a torque-free body at time t (s): c moves uniformly, L and P stay.
BodyState exact_free_state(const RigidBodyModel& m, const BodyState& s0, double t);

/// One `exact` step: the closed-form rotation over h, Strang-composed with half
/// kicks when the body has forces or torques.
BodyState exact_step(const RigidBodyModel& m, const BodyState& s, double t, double h);

}  // namespace tumble
