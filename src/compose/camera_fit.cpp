#include "compose/camera_fit.hpp"

#include <algorithm>
#include <cmath>

#include "compose/view_layout.hpp"

namespace tumble::compose {

namespace {

bool fits(const Shot& s, double factor, double aspect, Margins margin) {
  const CameraMatrices m = camera_matrices(backed_off(s.camera, factor), static_cast<float>(aspect));
  const double lim_x = 1.0 - margin.x, lim_y = 1.0 - margin.y;
  for (const glm::dvec3& p : s.points) {
    const glm::vec4 clip = m.proj * m.view * glm::vec4(glm::vec3(p), 1.0f);
    if (clip.w <= 0 || clip.z < -clip.w) return false;  // behind the camera or before its near plane
    if (std::abs(clip.x / clip.w) > lim_x || std::abs(clip.y / clip.w) > lim_y) return false;
  }
  return true;
}

}  // namespace

viz::Camera backed_off(viz::Camera c, double factor) {
  const glm::dvec3 eye = c.position - c.target;
  c.position = c.target + factor * eye;
  c.far_m = c.far_m + (factor - 1) * glm::length(eye);
  return c;
}

double backoff(const std::vector<Shot>& shots, double aspect, Margins margin, double closest) {
  const auto all = [&](double f) {
    return std::all_of(shots.begin(), shots.end(), [&](const Shot& s) { return fits(s, f, aspect, margin); });
  };
  if (all(1.0)) {
    if (closest >= 1.0 || all(closest)) return std::min(1.0, closest);
    double lo = closest, hi = 1.0;  // lo does not fit, hi does
    for (int i = 0; i < 30; ++i) {
      const double mid = 0.5 * (lo + hi);
      (all(mid) ? hi : lo) = mid;
    }
    return hi;
  }
  double lo = 1.0, hi = 2.0;
  while (!all(hi) && hi < 64) lo = hi, hi *= 2;
  for (int i = 0; i < 30; ++i) {
    const double mid = 0.5 * (lo + hi);
    (all(mid) ? hi : lo) = mid;
  }
  return hi;
}

std::vector<glm::dvec3> solid_points(const viz::View& v) {
  std::vector<glm::dvec3> out;
  for (const viz::BoxItem& b : v.boxes)
    for (const glm::dvec3& p : viz::box_corners(b)) out.push_back(p);
  for (const viz::ArrowItem& a : v.arrows) out.insert(out.end(), {a.origin, a.origin + a.vector});
  for (const viz::PointItem& p : v.points)
    if (!p.name.empty()) out.push_back(p.position);
  return out;
}

}  // namespace tumble::compose
