// The keyframes of a glTF export: at least `fps` per second, plus keys where
// a body turns or accelerates fast, so that what a viewer interpolates
// between keys (LINEAR: lerp of the centre of mass, slerp the short way of
// the rotation) stays within a stated tolerance of the simulation.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "scene/sampled_run.hpp"
#include "scene/scene.hpp"

namespace tumble::gltf {

/// Default largest rotation error between keys, rad. A point 1000 px from the
/// centre of mass (a body filling a 4K frame) moves under a pixel.
inline constexpr double kKeyTolerance = 1e-3;
/// The range `--key-tolerance` accepts, rad: float32 keys hold ~1e-7.
inline constexpr double kMinKeyTolerance = 1e-5, kMaxKeyTolerance = 0.5;
/// Most keys one body may get: past this the export is refused, naming the fix.
inline constexpr std::size_t kMaxKeysPerBody = 1'000'000;

struct KeyOptions {
  double fps = 0;                      ///< keys per second at least; 0: the scene's output fps
  double tolerance = kKeyTolerance;    ///< rad; the centre of mass within tolerance × the body's radius
  std::size_t max_keys = kMaxKeysPerBody;
  std::string tolerance_name = "--key-tolerance";  ///< how messages name the tolerance (a Python argument)
};

/// The times every export keys: k/fps up to the scene's duration (the last is
/// the duration), fps = `fps` or, when 0, the scene's output fps.
std::vector<double> keyframe_times(const scene::Scene& s, double fps = 0);

/// Each body's keys: the samples at keyframe_times(s, o.fps) (equal to
/// scene::sample_run's) and, between two of them, as many more samples of the
/// same run as it takes for every check point in between to lie within the
/// tolerance of the linear interpolation of the keys: angle(slerp(q_a, q_b,
/// u), q) <= 0.9 tolerance and |lerp(c_a, c_b, u) - c| <= 0.9 tolerance ×
/// viz::box_radius. Check points are so close that the motion between two of
/// them departs from their chord by 2 % of the tolerance (|α| h²/8 and
/// |a| h²/8 at the earlier one) and at most 0.1 rad apart. Throws InputError
/// naming --key-tolerance past o.max_keys keys, Diverged as the run does.
/// `poll` runs after each sample (it may throw).
std::vector<scene::Trajectory> key_tracks(const scene::Scene& s, const KeyOptions& o,
                                          const std::function<void()>& poll = {});

}  // namespace tumble::gltf
