// Cameras fitted to a content rectangle: what a view shows over the whole
// video stays inside it, so nothing is clipped at its edges.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "viz/draw_list.hpp"

namespace tumble::compose {

/// One frame's camera and the points it must show (world, m): the bodies'
/// and the arrows' tips, which carry names beyond them and so may need more room.
struct Shot {
  viz::Camera camera;
  std::vector<glm::dvec3> points;
  std::vector<glm::dvec3> tips = {};
};

/// Room kept clear at the content's edges: fractions of its half width (x) and half height (y).
struct Margins {
  double x, y;
  Margins(double both) : x(both), y(both) {}  // NOLINT: a plain number means both
  Margins(double x_, double y_) : x(x_), y(y_) {}
};

/// The smallest factor >= `closest` by which every shot's camera may move
/// back from its target (same direction; a factor under 1 moves it closer) so
/// that all its points project inside a content rectangle of `aspect`
/// (width/height), `margin` in from its edges, in front of the near plane.
/// Perspective cameras only. With `closest` = 1 (the default) cameras only
/// back off: 1 when they fit. Tips keep `tip_margin` (at least `margin`).
double backoff(const std::vector<Shot>& shots, double aspect, Margins margin, double closest = 1.0,
               Margins tip_margin = 0.0);

/// `c` moved `factor` times as far from its target, its far plane with it.
viz::Camera backed_off(viz::Camera c, double factor);

/// A few vertices of each mesh or particle set, kept while a camera is fitted
/// (its items' shared sets outlive it): see `solid_shot`.
class Outlines {
 public:
  /// The vertices of `points` that lie farthest along each of kDirections directions (no copies).
  const std::vector<glm::vec3>& of(const void* key, const std::vector<glm::vec3>& points);
  static constexpr int kDirections = 64;

 private:
  std::vector<std::pair<const void*, std::vector<glm::vec3>>> cache_;
};

/// The points a view of bodies must show: what it draws of each body (the
/// box when drawn; else its surfaces' and particles' outermost vertices), and
/// every arrow's tail and tip.
std::vector<glm::dvec3> solid_points(const viz::View& v);
/// The same as a shot: bodies, arrow tails and named points in `points`, arrow tips in `tips`.
/// `outlines` keeps each mesh's outermost vertices from one frame to the next.
Shot solid_shot(const viz::View& v, Outlines& outlines);
Shot solid_shot(const viz::View& v);

/// `c` moved across its line of sight (target with it) so that every shot's
/// points and tips, seen through it `factor` times as far back, are centred
/// in a content rectangle of `aspect`: what sticks out further on one side
/// (L's line above a body) no longer leaves the other side empty.
viz::Camera centred(viz::Camera c, const std::vector<Shot>& shots, double aspect, double factor);

}  // namespace tumble::compose
