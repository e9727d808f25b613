#include "viz/end_on_mark.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "viz/palette.hpp"

namespace tumble::viz {

void add_end_on_marks(View& view, double reach, double radius) {
  const glm::dvec3 to_eye = glm::normalize(view.camera.position - view.camera.target);
  const glm::dvec3 right = glm::normalize(glm::cross(glm::dvec3(view.camera.up), to_eye));
  const glm::dvec3 up = glm::cross(to_eye, right);
  const double full = std::cos(kEndOnDeg * std::numbers::pi / 180), none = std::cos(kEndOnFadeDeg * std::numbers::pi / 180);
  for (int i = 0; i < 3; ++i)
    for (int sign : {1, -1}) {
      glm::dvec3 end(0);
      end[i] = sign * reach;
      const double c = glm::dot(glm::normalize(end), to_eye);
      if (c <= none) continue;
      const float strength = static_cast<float>(std::clamp((c - none) / (full - none), 0.0, 1.0));
      std::vector<glm::dvec3> ring;
      for (int k = 0; k <= 40; ++k) {
        const double a = 2 * std::numbers::pi * k / 40;
        ring.push_back(end + radius * (std::cos(a) * right + std::sin(a) * up));
      }
      const std::string name = std::string(sign > 0 ? "end_on_e" : "end_on_-e") + char('1' + i);
      view.polylines.push_back({std::move(ring), color_of(static_cast<Meaning>(i), strength), 2.5f, false, name});
    }
}

}  // namespace tumble::viz
