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

/// The smallest factor >= 1 by which every shot's camera may move back from
/// its target (same direction) so that all its points project inside a
/// content rectangle of `aspect` (width/height), `margin` (a fraction of its
/// half size) in from each edge. Perspective cameras only; 1 when they fit.
double backoff(const std::vector<Shot>& shots, double aspect, double margin);

/// `c` moved `factor` times as far from its target, its far plane with it.
viz::Camera backed_off(viz::Camera c, double factor);

/// The points a view of bodies must show: each body's box corners and every arrow's tail and tip.
std::vector<glm::dvec3> solid_points(const viz::View& v);

}  // namespace tumble::compose
