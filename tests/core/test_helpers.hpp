// Small helpers shared by the core tests: bodies given by their principal
// moments, fixed-step runs, and geometric error measures.
#pragma once

#include <cmath>
#include <string>

#include "core/body.hpp"
#include "core/dynamics.hpp"
#include "core/integrator.hpp"
#include "core/quaternion.hpp"

namespace tumble::testing {

/// A body given directly by its principal moments (principal frame = cloud frame).
inline RigidBodyModel body_with_moments(const Eigen::Vector3d& inertia, double mass = 1.0,
                                        const std::string& name = "body") {
  RigidBodyModel m;
  m.name = name;
  m.mass = mass;
  m.inertia = inertia;
  m.inv_inertia = inertia.cwiseInverse();
  return m;
}

/// State with world ← principal orientation q and body-frame angular velocity ω (rad/s).
inline BodyState spinning_state(const RigidBodyModel& m, const Eigen::Quaterniond& q,
                                const Eigen::Vector3d& omega_principal) {
  BodyState s;
  s.q = q.normalized();
  s.L = s.q * m.inertia.cwiseProduct(omega_principal);
  return s;
}

/// n fixed steps of size h from t = 0.
inline BodyState run_steps(Method method, const RigidBodyModel& m, BodyState s, double h, long n) {
  for (long i = 0; i < n; ++i) s = step(method, m, s, static_cast<double>(i) * h, h);
  return s;
}

/// Angle (rad) between two vectors, accurate near 0 and π.
inline double angle_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

/// Angle (rad) between principal axis `axis` of the body (in world) and world L.
inline double tilt_from_L(const BodyState& s, int axis) {
  return angle_between(s.q * Eigen::Vector3d::Unit(axis), s.L);
}

inline std::string name_of(Method m) { return std::string(method_name(m)); }

}  // namespace tumble::testing
