// Cameras fitted to a content rectangle: what a view shows over the whole
// video stays inside it, so nothing is clipped at its edges.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "viz/draw_list.hpp"

namespace tumble::compose {

/// One frame's camera and the points it must show (world, m).
struct Shot {
  viz::Camera camera;
  std::vector<glm::dvec3> points;
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
/// back off: 1 when they fit.
double backoff(const std::vector<Shot>& shots, double aspect, Margins margin, double closest = 1.0);

/// `c` moved `factor` times as far from its target, its far plane with it.
viz::Camera backed_off(viz::Camera c, double factor);

/// The points a view of bodies must show: each body's box corners and every arrow's tail and tip.
std::vector<glm::dvec3> solid_points(const viz::View& v);

}  // namespace tumble::compose
