// Small quaternion helpers. Eigen stores coefficients as (x, y, z, w).
#pragma once

#include <cmath>

#include <Eigen/Geometry>

namespace tumble {

/// exp of the pure quaternion (0, v/2): the rotation by angle |v| (rad) about v.
/// Uses sin(θ/2)/θ with a series near 0 so tiny rotations keep full precision.
inline Eigen::Quaterniond quat_exp(const Eigen::Vector3d& v) {
  const double theta = v.norm();
  const double half = 0.5 * theta;
  const double s = theta < 1e-4 ? 0.5 - theta * theta / 48.0 : std::sin(half) / theta;
  return Eigen::Quaterniond(std::cos(half), s * v.x(), s * v.y(), s * v.z());
}

/// Rotation by `angle` (rad) about principal axis `axis` (0, 1, 2).
inline Eigen::Quaterniond axis_rotation(int axis, double angle) {
  Eigen::Quaterniond q(std::cos(0.5 * angle), 0, 0, 0);
  q.vec()[axis] = std::sin(0.5 * angle);
  return q;
}

/// Eigen's q * v (QuaternionBase::_transformVector) in scalars, the same
/// operations in the same order, so the same bits: uv = u × v, uv += uv,
/// v + w·uv + u × uv. gcc -O2 leaves Eigen's out of line with packed
/// temporaries (~20 ns); this inlines (~3 ns). q unit (x, y, z, w).
[[gnu::always_inline]] inline void rotate(double x, double y, double z, double w, const double v[3], double out[3]) {
  double a = y * v[2] - z * v[1], b = z * v[0] - x * v[2], c = x * v[1] - y * v[0];
  a += a;
  b += b;
  c += c;
  out[0] = (v[0] + w * a) + (y * c - z * b);
  out[1] = (v[1] + w * b) + (z * a - x * c);
  out[2] = (v[2] + w * c) + (x * b - y * a);
}

/// q v q̄ (= Eigen's q * v, same bits).
inline Eigen::Vector3d rotate(const Eigen::Quaterniond& q, const Eigen::Vector3d& v) {
  Eigen::Vector3d o;
  rotate(q.x(), q.y(), q.z(), q.w(), v.data(), o.data());
  return o;
}

/// q̄ v q (= Eigen's q.conjugate() * v, same bits): world → body for q = world ← body.
inline Eigen::Vector3d rotate_inverse(const Eigen::Quaterniond& q, const Eigen::Vector3d& v) {
  Eigen::Vector3d o;
  rotate(-q.x(), -q.y(), -q.z(), q.w(), v.data(), o.data());
  return o;
}

/// Pure quaternion (0, v).
inline Eigen::Quaterniond pure(const Eigen::Vector3d& v) { return Eigen::Quaterniond(0, v.x(), v.y(), v.z()); }

/// Picks the sign of q that is closest to `ref` (q and -q are the same rotation);
/// keeps output quaternions continuous in time.
inline Eigen::Quaterniond same_hemisphere(const Eigen::Quaterniond& q, const Eigen::Quaterniond& ref) {
  return q.dot(ref) < 0 ? Eigen::Quaterniond(-q.coeffs()) : q;
}

/// Angle (rad, in [0, π]) of the rotation taking a to b: the orientation error metric.
inline double rotation_angle_between(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  const double d = std::abs(a.normalized().dot(b.normalized()));
  // 2·atan2(|vec|, |w|) of a⁻¹b is accurate near 0 where 2·acos(d) is not.
  const Eigen::Quaterniond r = a.normalized().conjugate() * b.normalized();
  (void)d;
  return 2.0 * std::atan2(r.vec().norm(), std::abs(r.w()));
}

}  // namespace tumble
