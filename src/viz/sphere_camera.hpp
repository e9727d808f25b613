// The momentum sphere's camera: it follows Π so that Π and its recent path
// stay on the near hemisphere. Its direction is Π̂ low-pass filtered in
// simulated time (an exponential slerp with time constant `follow_s`) and
// never more than `max_lag_deg` behind; its up vector is carried along by the
// smallest rotation (parallel transport) and relaxes towards +e₃ where that is
// defined. Each step is a continuous function of the samples, so the camera
// turns smoothly and never snaps, and pose j depends only on samples 0…j: a
// frame rendered alone equals the same frame of a full run.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "viz/draw_list.hpp"

namespace tumble::viz {

/// Where the camera looks from, principal frame: unit `dir` (centre → camera's
/// reference point) and unit `up` ⊥ dir.
struct SpherePose {
  Eigen::Vector3d dir{-0.6, 0.6, 0.55};
  Eigen::Vector3d up{0, 0, 1};
};

/// [[views]] camera of the momentum_sphere (and poinsot) views.
struct SphereCameraSettings {
  double azimuth_deg = 25;     ///< around `up`, from the followed direction (or from +e1 when fixed)
  double elevation_deg = 20;   ///< above it, towards `up`
  double distance = 5.2;       ///< in sphere radii (|L|)
  bool follow = true;          ///< false: fixed at azimuth/elevation in the principal frame, up = +e3 (at elevation ±90: the azimuth's direction)
  double follow_s = 0.15;      ///< time constant of the filter, simulated s
  double max_lag_deg = 35;     ///< the followed direction stays this close to Π̂
  double max_turn_deg = 60;    ///< ... and this close to where it started: the figure never turns round
  Eigen::Vector3d up{0, 0, 0}; ///< fixed camera: the picture's up (principal axes); zero: +e3
  double reach = 1.5;          ///< half the view's height, in |L| (the momentum sphere: its axis labels)
};

/// Half the momentum sphere view's height, |L|: its axes (1.22) and their labels fit.
inline constexpr double kSphereReach = 1.5;

/// The momentum sphere's default camera, a fixed textbook view for a body
/// whose Π starts at `pi0` (principal moments `inertia`, ascending): it looks
/// from the side of the pole its polhode circles (e₁ or e₃, on Π's side),
/// tilted 12° from it towards the other pole's axis, with ±e₂ across the
/// picture on the rim: the whole polhode lies in front (a loop near the
/// separatrix runs from saddle to saddle over the near hemisphere); the far
/// end of the pole's axis lies behind the ball (not named); from far away
/// (distance 14), nearly without perspective.
SphereCameraSettings textbook_camera(const Eigen::Vector3d& inertia, const Eigen::Vector3d& pi0);

/// Poses at each sample (times `t`, s, ascending; Π in the principal frame).
std::vector<SpherePose> follow_track(const std::vector<double>& t, const std::vector<Eigen::Vector3d>& pi,
                                     const SphereCameraSettings& s);

/// The camera at `pose` (follow) or at the fixed direction (no follow).
Camera sphere_camera(const SpherePose& pose, const SphereCameraSettings& s);

/// The vertical field of view, degrees, that shows a ball of `radius` around
/// `c`'s target whole in a rectangle of `aspect` (width / height).
double fov_for_ball(const Camera& c, double radius, double aspect);

/// True when the segment from `eye` to `p` passes through the ball of radius
/// `r` at the origin (p itself outside it): p is hidden behind the ball.
bool hidden_by_ball(const glm::dvec3& eye, const glm::dvec3& p, double r);

}  // namespace tumble::viz
