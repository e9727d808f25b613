#include "compose/camera_fit.hpp"

#include <algorithm>
#include <cmath>

#include "compose/view_layout.hpp"

namespace tumble::compose {

namespace {

bool inside(const CameraMatrices& m, const std::vector<glm::dvec3>& points, Margins margin) {
  const double lim_x = 1.0 - margin.x, lim_y = 1.0 - margin.y;
  for (const glm::dvec3& p : points) {
    const glm::vec4 clip = m.proj * m.view * glm::vec4(glm::vec3(p), 1.0f);
    if (clip.w <= 0 || clip.z < -clip.w) return false;  // behind the camera or before its near plane
    if (std::abs(clip.x / clip.w) > lim_x || std::abs(clip.y / clip.w) > lim_y) return false;
  }
  return true;
}

bool fits(const Shot& s, double factor, double aspect, Margins margin, Margins tip_margin) {
  const CameraMatrices m = camera_matrices(backed_off(s.camera, factor), static_cast<float>(aspect));
  return inside(m, s.points, margin) &&
         inside(m, s.tips, {std::max(margin.x, tip_margin.x), std::max(margin.y, tip_margin.y)});
}

}  // namespace

viz::Camera backed_off(viz::Camera c, double factor) {
  const glm::dvec3 eye = c.position - c.target;
  c.position = c.target + factor * eye;
  c.far_m = c.far_m + (factor - 1) * glm::length(eye);
  return c;
}

double backoff(const std::vector<Shot>& shots, double aspect, Margins margin, double closest, Margins tip_margin) {
  const auto all = [&](double f) {
    return std::all_of(shots.begin(), shots.end(), [&](const Shot& s) { return fits(s, f, aspect, margin, tip_margin); });
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

const std::vector<glm::vec3>& Outlines::of(const void* key, const std::vector<glm::vec3>& points) {
  for (const auto& [k, out] : cache_)
    if (k == key) return out;
  // Directions spread evenly over the sphere (a Fibonacci lattice): the
  // vertices farthest along them bound the set's projection to within a few
  // per cent, and a fit keeps a margin larger than that.
  std::vector<glm::vec3> out;
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < kDirections && !points.empty(); ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / kDirections, r = std::sqrt(1.0 - z * z);
    const glm::vec3 d(float(r * std::cos(golden * i)), float(r * std::sin(golden * i)), float(z));
    const auto far = std::max_element(points.begin(), points.end(),
                                      [&](const glm::vec3& a, const glm::vec3& b) { return glm::dot(a, d) < glm::dot(b, d); });
    if (std::find(out.begin(), out.end(), *far) == out.end()) out.push_back(*far);
  }
  cache_.emplace_back(key, std::move(out));
  return cache_.back().second;
}

Shot solid_shot(const viz::View& v) {
  Outlines outlines;
  return solid_shot(v, outlines);
}

Shot solid_shot(const viz::View& v, Outlines& outlines) {
  Shot s{v.camera, {}, {}};
  for (const viz::BoxItem& b : v.boxes)
    for (const glm::dvec3& p : viz::box_corners(b)) s.points.push_back(p);
  // Surfaces and particles as drawn (a hidden box is no part of the picture).
  const auto add = [&](const glm::dmat4& model, const std::vector<glm::vec3>& outline) {
    for (const glm::vec3& p : outline) s.points.push_back(glm::dvec3(model * glm::dvec4(glm::dvec3(p), 1.0)));
  };
  for (const viz::SurfaceItem& f : v.surfaces)
    if (f.mesh) add(f.model, outlines.of(f.mesh.get(), f.mesh->positions));
  for (const viz::ParticlesItem& p : v.particles)
    if (p.set && !p.set->levels.empty()) add(p.model, outlines.of(p.set.get(), p.set->levels.front().positions));
  for (const viz::ArrowItem& a : v.arrows) {
    s.points.push_back(a.origin);
    s.tips.push_back(a.origin + a.vector);
  }
  for (const viz::PointItem& p : v.points)
    if (!p.name.empty()) s.points.push_back(p.position);
  return s;
}

viz::Camera centred(viz::Camera c, const std::vector<Shot>& shots, double aspect, double factor) {
  // Twice: a perspective camera moved sideways sees near and far points shift by different amounts.
  for (int pass = 0; pass < 2; ++pass) {
    const CameraMatrices m = camera_matrices(backed_off(c, factor), static_cast<float>(aspect));
    glm::dvec2 lo(1e30), hi(-1e30);
    for (const Shot& s : shots)
      for (const auto* set : {&s.points, &s.tips})
        for (const glm::dvec3& p : *set) {
          const glm::vec4 clip = m.proj * m.view * glm::vec4(glm::vec3(p), 1.0f);
          if (clip.w <= 0) return c;  // something behind the camera: leave it as the fit found it
          const glm::dvec2 ndc(clip.x / clip.w, clip.y / clip.w);
          lo = glm::min(lo, ndc), hi = glm::max(hi, ndc);
        }
    if (lo.x > hi.x) return c;
    const glm::dvec2 mid = 0.5 * (lo + hi);
    // NDC ±1 spans tan(fov/2) of the distance, at the target's depth.
    const glm::dvec3 eye = backed_off(c, factor).position, look = glm::normalize(c.target - eye);
    const glm::dvec3 up = glm::normalize(viz::view_up(c)), right = glm::normalize(glm::cross(look, up));
    const double half_h = glm::length(c.target - eye) * std::tan(0.5 * glm::radians(c.fov_y_deg));
    const glm::dvec3 shift = mid.x * half_h * aspect * right + mid.y * half_h * glm::normalize(glm::cross(right, look));
    c.position += shift, c.target += shift;
  }
  return c;
}

std::vector<glm::dvec3> solid_points(const viz::View& v) {
  Shot s = solid_shot(v);
  s.points.insert(s.points.end(), s.tips.begin(), s.tips.end());
  return s.points;
}

}  // namespace tumble::compose
