#include "viz/angle_arc.hpp"

#include <algorithm>
#include <cmath>

namespace tumble::viz {

std::vector<glm::dvec3> angle_arc_points(const glm::dvec3& centre, const glm::dvec3& from, const glm::dvec3& to, double radius,
                                         double min_deg) {
  if (glm::length(from) <= 0 || glm::length(to) <= 0) return {};
  const glm::dvec3 a = glm::normalize(from), b = glm::normalize(to);
  const double angle = std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
  if (glm::degrees(angle) < min_deg) return {};
  // b's part square to a: the arc turns in the plane of a and b (slerp).
  const glm::dvec3 side = glm::normalize(b - glm::dot(a, b) * a);
  const int n = std::max(3, static_cast<int>(std::ceil(glm::degrees(angle) / 2)) + 1);
  std::vector<glm::dvec3> out;
  for (int i = 0; i < n; ++i) {
    const double s = angle * i / (n - 1);
    out.push_back(centre + radius * (std::cos(s) * a + std::sin(s) * side));
  }
  return out;
}

PolylineItem angle_arc(const glm::dvec3& centre, const glm::dvec3& from, const glm::dvec3& to, double radius, Color color,
                       float width_px) {
  return {angle_arc_points(centre, from, to, radius), color, width_px, false, "angle_arc"};
}

}  // namespace tumble::viz
