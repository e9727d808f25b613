#include "viz/dashes.hpp"

#include <algorithm>

namespace tumble::viz {

std::vector<std::vector<glm::dvec3>> dashed(const std::vector<glm::dvec3>& curve, double on, double off) {
  std::vector<std::vector<glm::dvec3>> out;
  double s = 0;
  bool drawing = true;
  std::vector<glm::dvec3> dash{curve.empty() ? glm::dvec3(0) : curve.front()};
  for (std::size_t i = 1; i < curve.size(); ++i) {
    glm::dvec3 a = curve[i - 1];
    double left = glm::length(curve[i] - a);
    while (left > 0) {
      const double room = (drawing ? on : off) - s, step = std::min(room, left);
      const glm::dvec3 b = a + (curve[i] - a) * (step / std::max(left, 1e-300));
      if (drawing) dash.push_back(b);
      s += step, left -= step, a = b;
      if (s >= (drawing ? on : off) - 1e-12) {
        if (drawing && dash.size() >= 2) out.push_back(std::move(dash));
        dash = {a};
        drawing = !drawing, s = 0;
      }
    }
  }
  if (drawing && dash.size() >= 2) out.push_back(std::move(dash));
  return out;
}

}  // namespace tumble::viz
