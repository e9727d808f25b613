#include "viz/sphere_camera.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

namespace tumble::viz {

namespace {

constexpr double kDeg = std::numbers::pi / 180;

// Unit vector ⊥ `d` nearest `preferred` (or, when preferred ∥ d, nearest e1).
Eigen::Vector3d perpendicular(const Eigen::Vector3d& d, const Eigen::Vector3d& preferred) {
  Eigen::Vector3d u = preferred - preferred.dot(d) * d;
  if (u.norm() < 1e-3) u = Eigen::Vector3d::UnitX() - d.x() * d;
  return u.normalized();
}

// Turns unit `a` towards unit `b` by the fraction `f` of the angle between them.
Eigen::Vector3d slerp(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double f) {
  const double angle = std::acos(std::clamp(a.dot(b), -1.0, 1.0));
  if (angle < 1e-12) return b;
  const Eigen::Vector3d axis = a.cross(b);
  if (axis.norm() < 1e-12) return a;  // opposite: no preferred turn; the lag clamp below cannot be hit
  return Eigen::AngleAxisd(f * angle, axis.normalized()) * a;
}

}  // namespace

std::vector<SpherePose> follow_track(const std::vector<double>& t, const std::vector<Eigen::Vector3d>& pi,
                                     const SphereCameraSettings& s) {
  std::vector<SpherePose> out;
  out.reserve(pi.size());
  const Eigen::Vector3d e3 = Eigen::Vector3d::UnitZ();
  const double max_lag = s.max_lag_deg * kDeg;
  for (std::size_t j = 0; j < pi.size(); ++j) {
    const Eigen::Vector3d target = pi[j].norm() > 0 ? Eigen::Vector3d(pi[j].normalized()) : Eigen::Vector3d::UnitY();
    SpherePose p;
    if (j == 0) {
      p.dir = target;
      p.up = perpendicular(target, e3);
      out.push_back(p);
      continue;
    }
    const SpherePose& prev = out.back();
    const double dt = std::max(0.0, t[j] - t[j - 1]);
    const double f = s.follow_s > 0 ? 1 - std::exp(-dt / s.follow_s) : 1.0;
    p.dir = slerp(prev.dir, target, f);
    // Never more than max_lag behind Π̂: keeps Π on the near side at any speed.
    const double lag = std::acos(std::clamp(p.dir.dot(target), -1.0, 1.0));
    if (lag > max_lag) p.dir = slerp(p.dir, target, 1 - max_lag / lag);
    // Never more than max_turn from the start: the figure keeps its bearings (what goes behind shows through).
    const double turn = std::acos(std::clamp(p.dir.dot(out.front().dir), -1.0, 1.0));
    if (turn > s.max_turn_deg * kDeg) p.dir = slerp(out.front().dir, p.dir, s.max_turn_deg * kDeg / turn);
    // Up carried by the smallest rotation, then relaxed (1 s) towards +e3 as far as e3 ⊥ dir exists.
    const Eigen::Vector3d carried = Eigen::Quaterniond::FromTwoVectors(prev.dir, p.dir) * prev.up;
    const Eigen::Vector3d e3_perp = e3 - e3.dot(p.dir) * p.dir;
    const double weight = std::min(1.0, dt / 1.0) * e3_perp.squaredNorm();
    p.up = perpendicular(p.dir, carried + weight * e3_perp);
    out.push_back(p);
  }
  return out;
}

Camera sphere_camera(const SpherePose& pose, const SphereCameraSettings& s) {
  const double az = s.azimuth_deg * kDeg, el = s.elevation_deg * kDeg;
  Eigen::Vector3d dir, up;
  if (s.follow) {
    const Eigen::Vector3d side = pose.up.cross(pose.dir);
    dir = std::cos(el) * (std::cos(az) * pose.dir + std::sin(az) * side) + std::sin(el) * pose.up;
    up = pose.up;
  } else {
    dir = {std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
    // Straight down ±e3 the azimuth's direction is up (elevation 90, azimuth 90: +e2 at the top).
    const bool down_e3 = std::abs(std::abs(s.elevation_deg) - 90) < 1e-9;
    up = down_e3 ? Eigen::Vector3d(std::cos(az), std::sin(az), 0) : Eigen::Vector3d::UnitZ();
    // A chosen up (e.g. +e₂, as the body's own view stands), unless it lies along the view.
    if (s.up.norm() > 0 && s.up.normalized().cross(dir).norm() > 1e-3) up = s.up.normalized();
  }
  Camera c;
  const Eigen::Vector3d eye = s.distance * dir.normalized();
  c.position = {eye.x(), eye.y(), eye.z()};
  c.target = {0, 0, 0};
  c.up = {up.x(), up.y(), up.z()};
  c.fov_y_deg = 2 * std::atan(s.reach / s.distance) / kDeg;  // the sphere and its axes fill the height
  c.near_m = 0.1 * s.distance;
  c.far_m = 4 * s.distance;
  return c;
}

SphereCameraSettings textbook_camera(const Eigen::Vector3d& inertia, const Eigen::Vector3d& pi0) {
  const double L = pi0.norm();
  const double two_E = L > 0 ? pi0.cwiseAbs2().cwiseQuotient(inertia).sum() : 0;
  // The pole the polhode circles: e1 above the separatrix level L²/I2, e3 below.
  const int pole = L > 0 && two_E > L * L / inertia[1] ? 0 : 2, other = 2 - pole;
  auto sign = [](double x) { return x < 0 ? -1.0 : 1.0; };
  // 12°: the pole's loop is seen nearly from above, both separatrix circles
  // open (they lean about 30° from e₃ for a T-handle, either way), ±e₂ on the
  // rim left and right; the far end of the pole's axis is behind the ball.
  constexpr double kTilt = 12 * kDeg;
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  d[pole] = std::cos(kTilt) * sign(pi0[pole]);
  d[other] = std::sin(kTilt) * sign(pi0[other]);
  SphereCameraSettings s;
  s.follow = false;
  s.azimuth_deg = std::atan2(d.y(), d.x()) / kDeg;
  s.elevation_deg = std::asin(std::clamp(d.z(), -1.0, 1.0)) / kDeg;
  s.distance = 14;
  s.reach = kSphereReach;
  return s;
}

double fov_for_ball(const Camera& c, double radius, double aspect) {
  const double d = glm::length(c.position - c.target);
  const double half = std::asin(std::clamp(radius / std::max(d, 1e-12), 0.0, 0.99));
  // Up and down tan(half) of the height; across, the same angle needs aspect times it.
  return glm::degrees(2 * std::atan(std::tan(half) / std::min(1.0, aspect)));
}

bool hidden_by_ball(const glm::dvec3& eye, const glm::dvec3& p, double r) {
  const glm::dvec3 d = p - eye;
  const double len2 = glm::dot(d, d);
  if (len2 <= 0) return false;
  // Closest approach of the segment to the origin.
  const double s = std::clamp(-glm::dot(eye, d) / len2, 0.0, 1.0);
  const glm::dvec3 closest = eye + s * d;
  return s < 1.0 && glm::dot(closest, closest) < r * r;
}

}  // namespace tumble::viz
