// A curve cut into dashes: a separatrix reads as "a boundary", not as a path.
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace tumble::viz {

/// `curve` as dashes `on` long with gaps `off` (lengths along it, the curve's units).
std::vector<std::vector<glm::dvec3>> dashed(const std::vector<glm::dvec3>& curve, double on, double off);

}  // namespace tumble::viz
