// Geometric one-step methods: the torque-free rotation advanced by a map that
// keeps world L (and, for the midpoint rule, energy) exactly, with forces and
// torques entering as Strang half kicks (`kick` in dynamics.hpp).
#pragma once

#include "core/body.hpp"

namespace tumble {

/// Torque-free rotation maps: advance q (world ← principal) over h (s) with
/// world L fixed; the model supplies the principal moments.
using FreeRotationMap = void (*)(const RigidBodyModel& m, const Eigen::Vector3d& L,
                                 Eigen::Quaterniond& q, double h);

/// NO_SQUISH / Dullweber–Leimkuhler–McLachlan (J. Chem. Phys. 107, 1997) splitting
/// H = T1 + T2 + T3 with Tᵢ = Πᵢ²/(2Iᵢ); each Tᵢ flow is an exact rotation about
/// principal axis i. Symmetric sequence A(h/2) B(h/2) C(h) B(h/2) A(h/2): order 2,
/// with the axes (A, B, C) chosen per body from its moments (kernel::split_order:
/// 3,2,1,2,3 for most bodies, 2,3,1,3,2 for elongated ones).
void free_rotation_splitting(const RigidBodyModel& m, const Eigen::Vector3d& L,
                             Eigen::Quaterniond& q, double h);
/// The same with the sub-flow order given (index into kernel::kSplitAxes).
void free_rotation_splitting(const RigidBodyModel& m, const Eigen::Vector3d& L, Eigen::Quaterniond& q, double h,
                             int order);

/// The same map (same sub-flow order) in plain form, in the seed's words: Π = q̄ L, then for each
/// sub-flow i over τ the body turns by θ = τ Πᵢ/Iᵢ about principal axis i
/// (Π turns by -θ: libm sin/cos, Eigen quaternion products), q ← normalise(q ⊗ r).
/// The reference the tuned kernel (splitting_kernel.hpp) is held to.
void free_rotation_splitting_reference(const RigidBodyModel& m, const Eigen::Vector3d& L,
                                       Eigen::Quaterniond& q, double h, int order);

/// Implicit midpoint rule on Euler's equations Π' = Π × I⁻¹Π (GNI IV.2.1: it keeps
/// every quadratic invariant, so |Π|² and 2T, to round-off). Its update is
/// Π₁ = cay(h ω̂ₘ)ᵀ Π₀, so advancing q by the same Cayley rotation keeps world L.
void free_rotation_midpoint(const RigidBodyModel& m, const Eigen::Vector3d& L,
                            Eigen::Quaterniond& q, double h);

/// Kick(h/2) ∘ [c += hP/M, free rotation map over h] ∘ Kick(h/2). A body without
/// forces skips the kicks; without torque its L is kept bit-for-bit.
BodyState strang_step(const RigidBodyModel& m, const BodyState& s, double t, double h,
                      FreeRotationMap rotate);

BodyState splitting_step(const RigidBodyModel& m, const BodyState& s, double t, double h);
/// The same step with the sub-flow order given (index into kernel::kSplitAxes):
/// a run fixes it at its start (kernel::split_order_for_start, FixedStepper).
BodyState splitting_step_ordered(const RigidBodyModel& m, const BodyState& s, double t, double h, int order);
/// Yoshida's triple jump (Phys. Lett. A 150, 1990) of the Strang splitting
/// step, with its own sub-flow order (kernel::split_order4): order 4.
BodyState splitting4_step(const RigidBodyModel& m, const BodyState& s, double t, double h);
BodyState implicit_midpoint_step(const RigidBodyModel& m, const BodyState& s, double t, double h);

/// Momenta first (P, L += h f(x₀)), then c += h v₁ and q ← exp(h ω_world(L₁)) ⊗ q. Order 1.
BodyState semi_implicit_euler_step(const RigidBodyModel& m, const BodyState& s, double t, double h);

}  // namespace tumble
