#include "gltf/keyframes.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "base/error.hpp"
#include "base/format.hpp"
#include "core/dynamics.hpp"
#include "viz/scene_view.hpp"

namespace tumble::gltf {

namespace {

/// Check points between keys hold the simulated motion's chord error to this
/// fraction of the tolerance (|a| h²/8 for a path of acceleration a).
constexpr double kChordShare = 0.02;
/// And are at most this far apart in rotation, rad (α is measured at the start).
constexpr double kMaxCheckTurn = 0.1;
/// Most check points between two keys of the --fps grid.
constexpr std::size_t kMaxChecks = 1'000'000;

/// A check point: the time, the body's state there and its world ← cloud rotation.
struct Pose {
  double t;
  BodyState state;
  Eigen::Quaterniond q;
};

/// The angle between two rotations, rad (whatever their signs).
double angle_between(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  const Eigen::Quaterniond r = a.conjugate() * b;
  return 2 * std::atan2(r.vec().norm(), std::abs(r.w()));
}

/// Whether a viewer's interpolation from key a to key b (lerp; slerp the short
/// way) is within `angle` (rad) and `distance` (m) of every pose between.
bool follows(const std::vector<Pose>& p, std::size_t a, std::size_t b, double angle, double distance) {
  Eigen::Quaterniond qb = p[b].q;
  if (p[a].q.dot(qb) < 0) qb.coeffs() = -qb.coeffs();
  const double span = p[b].t - p[a].t;
  for (std::size_t k = a + 1; k < b; ++k) {
    const double u = (p[k].t - p[a].t) / span;
    if (!(angle_between(p[a].q.slerp(u, qb), p[k].q) <= angle)) return false;
    if (!(((1 - u) * p[a].state.c + u * p[b].state.c - p[k].state.c).norm() <= distance)) return false;
  }
  return true;
}

/// The poses from p[a] to p[e] that become keys (e last): from each key, the
/// farthest pose it still follows() to, found by galloping then bisecting.
void choose_keys(const std::vector<Pose>& p, std::size_t a, std::size_t e, double angle, double distance,
                 std::vector<std::size_t>& keys) {
  while (a < e) {
    std::size_t good = a + 1, bad = e + 1;
    for (std::size_t step = 2;; step *= 2) {
      const std::size_t c = std::min(a + step, e);
      if (!follows(p, a, c, angle, distance)) {
        bad = c;
        break;
      }
      good = c;
      if (c == e) break;
    }
    while (bad - good > 1) {
      const std::size_t mid = good + (bad - good) / 2;
      (follows(p, a, mid, angle, distance) ? good : bad) = mid;
    }
    keys.push_back(good);
    a = good;
  }
}

/// The step to the next check point after `p` (s), up to `left`.
double check_step(const RigidBodyModel& m, const Pose& p, double tolerance, double radius, double left) {
  const double eps = kChordShare * tolerance;
  double h = std::min(left, kMaxCheckTurn / std::max(omega_world(m, p.state).norm(), 1e-300));
  const double alpha = angular_acceleration(m, p.state, p.t).norm(), acc = linear_acceleration(m, p.state, p.t).norm();
  if (alpha > 0) h = std::min(h, std::sqrt(8 * eps / alpha));
  if (acc > 0) h = std::min(h, std::sqrt(8 * eps * radius / acc));
  return h;
}

[[noreturn]] void refuse(const scene::Body& b, const std::string& what, const KeyOptions& o) {
  throw InputError("body '" + b.name + "': " + what + " to follow its motion within " + format_number(o.tolerance, 3) +
                   " rad between keys; raise " + o.tolerance_name + " (the rotation error allowed between keys, rad), "
                   "or shorten the scene's duration");
}

scene::Trajectory body_keys(scene::BodyRun& run, const std::vector<double>& base, const KeyOptions& o,
                            const std::function<void()>& poll) {
  const scene::Body& b = run.body();
  scene::Trajectory tr = scene::trajectory_header(run);
  const RigidBodyModel& m = b.model;
  const double radius = viz::box_radius(m), angle = 0.9 * o.tolerance, distance = angle * radius;
  auto pose = [&](double t) {
    const BodyState& st = run.at(t);
    if (poll) poll();
    return Pose{t, st, cloud_orientation(m, st)};
  };
  std::vector<Pose> checks{pose(base[0])};
  scene::append_sample(tr, base[0], m, checks[0].state);
  std::vector<std::size_t> keys;
  for (std::size_t k = 1; k < base.size(); ++k) {
    checks.erase(checks.begin(), checks.end() - 1);  // the last key starts the next interval
    while (checks.back().t < base[k]) {
      const double left = base[k] - checks.back().t;
      const double h = check_step(m, checks.back(), o.tolerance, radius, left);
      checks.push_back(pose(h >= left ? base[k] : checks.back().t + h));
      if (checks.size() > kMaxChecks) refuse(b, "more than " + format_number(kMaxChecks) + " check points between two keys are needed", o);
    }
    keys.clear();
    choose_keys(checks, 0, checks.size() - 1, angle, distance, keys);
    for (std::size_t i : keys) scene::append_sample(tr, checks[i].t, m, checks[i].state);
    if (tr.size() > o.max_keys) refuse(b, "more than " + format_number(static_cast<double>(o.max_keys)) + " keys are needed", o);
  }
  tr.steps = run.steps();
  return tr;
}

}  // namespace

std::vector<double> keyframe_times(const scene::Scene& s, double fps) {
  return scene::sample_times(s.simulation.duration, fps > 0 ? fps : s.render.output.fps);
}

std::vector<scene::Trajectory> key_tracks(const scene::Scene& s, const KeyOptions& o, const std::function<void()>& poll) {
  if (!(o.tolerance >= kMinKeyTolerance && o.tolerance <= kMaxKeyTolerance))
    throw InputError(o.tolerance_name + ": error: expected a number in [" + format_number(kMinKeyTolerance, 3) + ", " +
                     format_number(kMaxKeyTolerance, 3) + "] rad, found " + format_number(o.tolerance, 6));
  const std::vector<double> base = keyframe_times(s, o.fps);
  scene::SceneRun run(s, s.simulation);
  std::vector<scene::Trajectory> out;
  for (std::size_t i = 0; i < run.size(); ++i) out.push_back(body_keys(run.body(i), base, o, poll));
  return out;
}

}  // namespace tumble::gltf
