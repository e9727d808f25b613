// The angle between two directions drawn as an arc of a circle about a point
// (∠(ω, L) at a body): the angle reads even where perspective lays one arrow
// along the other.
#pragma once

#include <glm/glm.hpp>

#include "viz/draw_list.hpp"

namespace tumble::viz {

/// Points on the great-circle arc of radius `radius` about `centre` from
/// direction `from` to direction `to` (any lengths), one every ~2°, at least 3;
/// none when the angle is under `min_deg` (nothing to show) or a direction is zero.
std::vector<glm::dvec3> angle_arc_points(const glm::dvec3& centre, const glm::dvec3& from, const glm::dvec3& to, double radius,
                                         double min_deg = 0.5);

/// The arc as a curve of the draw list, named "angle_arc" (empty points: none).
PolylineItem angle_arc(const glm::dvec3& centre, const glm::dvec3& from, const glm::dvec3& to, double radius, Color color,
                       float width_px);

}  // namespace tumble::viz
