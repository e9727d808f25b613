// Forces and torques a body carries, as one list of small terms.
// Each kind of term says, in one place (this file and forces.cpp):
//   - `add_wrench`: its force (N) and torque about c (N·m), world frame, at a state;
//   - `add_kick`:   its part of the exact kick (c and q frozen, see KickPart);
//   - `potential`:  its potential energy (J), 0 unless conservative;
//   - `work`:       whether it is conservative, dissipative or driving.
// Everything else (the derivative, the splitting kicks, the energy balance,
// whether energy is conserved) is derived from the terms in core, so a new
// kind is one struct here, one row of kForceKinds and its tests.
#pragma once

#include <span>
#include <string_view>
#include <variant>
#include <vector>

#include <Eigen/Core>

namespace tumble {

struct RigidBodyModel;
struct BodyState;

enum class Frame { world, body };

/// Total force (N) and torque about c (N·m), world frame.
struct Wrench {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
};

/// How a term exchanges energy: `conservative` = minus the gradient of its
/// `potential`; `dissipative` = its power is never positive; `driving` = any
/// other (its work enters the energy balance as declared input).
enum class Work { conservative, dissipative, driving };

/// The sum of the terms' kicks: with c and q frozen over h, every kind tumble
/// has is affine in the momenta, P' = F - (k_lin/M) P and, per principal axis,
/// Π'ᵢ = τ_bᵢ - k_ang I⁻¹ᵢ Πᵢ, which `kick` (dynamics.hpp) solves in closed form.
struct KickPart {
  Wrench constant;           ///< wrench that does not depend on the momenta, world frame
  double linear_damping = 0;   ///< k_lin, N·s/m
  double angular_damping = 0;  ///< k_ang, N·m·s
};

/// Uniform gravity: force M g at c, no torque. Potential -M g·c.
struct UniformGravity {
  Eigen::Vector3d g = Eigen::Vector3d::Zero();  ///< m/s², world
  static constexpr Work work = Work::conservative;
  static constexpr bool torques = false;
  void add_wrench(const RigidBodyModel& m, const BodyState& s, Wrench& w) const;
  void add_kick(const RigidBodyModel& m, const BodyState& s, KickPart& k) const;
  double potential(const RigidBodyModel& m, const BodyState& s) const;
};

/// A constant force applied at a point fixed on the body (so it also yields torque).
struct PointForce {
  Eigen::Vector3d force;   ///< N, in `frame` (body = the cloud's own axes)
  Eigen::Vector3d point;   ///< m, cloud coordinates (as written in the scene)
  Frame frame = Frame::world;
  static constexpr Work work = Work::driving;
  static constexpr bool torques = true;
  void add_wrench(const RigidBodyModel& m, const BodyState& s, Wrench& w) const;
  void add_kick(const RigidBodyModel& m, const BodyState& s, KickPart& k) const;
  double potential(const RigidBodyModel&, const BodyState&) const { return 0; }
};

/// A constant torque (N·m) in `frame` (body = the cloud's own axes).
struct ConstantTorque {
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
  Frame frame = Frame::world;
  static constexpr Work work = Work::driving;
  static constexpr bool torques = true;
  void add_wrench(const RigidBodyModel& m, const BodyState& s, Wrench& w) const;
  void add_kick(const RigidBodyModel& m, const BodyState& s, KickPart& k) const;
  double potential(const RigidBodyModel&, const BodyState&) const { return 0; }
};

/// F = -k v (k in N·s/m): its kick is P's exact exponential decay.
struct LinearDamping {
  double k = 0;
  static constexpr Work work = Work::dissipative;
  static constexpr bool torques = false;
  void add_wrench(const RigidBodyModel& m, const BodyState& s, Wrench& w) const;
  void add_kick(const RigidBodyModel&, const BodyState&, KickPart& kp) const { kp.linear_damping += k; }
  double potential(const RigidBodyModel&, const BodyState&) const { return 0; }
};

/// τ = -k ω_world (k in N·m·s): its kick is Π's exact decay, axis by axis.
struct AngularDamping {
  double k = 0;
  static constexpr Work work = Work::dissipative;
  static constexpr bool torques = true;
  void add_wrench(const RigidBodyModel& m, const BodyState& s, Wrench& w) const;
  void add_kick(const RigidBodyModel&, const BodyState&, KickPart& kp) const { kp.angular_damping += k; }
  double potential(const RigidBodyModel&, const BodyState&) const { return 0; }
};

using ForceTerm = std::variant<UniformGravity, PointForce, ConstantTorque, LinearDamping, AngularDamping>;

/// The terms of one body, evaluated in list order (which fixes the rounding).
struct ForceSet {
  std::vector<ForceTerm> terms;

  bool empty() const { return terms.empty(); }
  /// True when some term produces a torque (the rotation is then not free).
  bool has_torque() const;
  /// True when total energy (kinetic + the terms' potentials) is an invariant:
  /// every term is conservative. Decided here, not by the callers (the
  /// overlay's |dE/E| is an error only then).
  bool conserves_energy() const;
  /// The first term of kind T, or nullptr.
  template <class T>
  const T* find() const {
    for (const ForceTerm& t : terms)
      if (const T* p = std::get_if<T>(&t)) return p;
    return nullptr;
  }
};

/// A scene key of a body that declares one term (the scene reader loops over
/// kForceKinds; gravity is scene-wide and point forces are a list of tables).
struct ForceKind {
  std::string_view key;  ///< body key in a scene
  bool vector;           ///< value is [x, y, z] (any); else one number ≥ 0
  std::string_view unit;
  /// The term for a nonzero value (v for vectors, x for numbers).
  ForceTerm (*make)(const Eigen::Vector3d& v, double x);
};
std::span<const ForceKind> force_kinds();

}  // namespace tumble
