#include "viz/surfaces.hpp"

#include <cmath>
#include <numbers>

namespace tumble::viz {

std::shared_ptr<const SurfaceMesh> unit_sphere_mesh() {
  static const std::shared_ptr<const SurfaceMesh> mesh = [] {
    auto m = std::make_shared<SurfaceMesh>();
    constexpr int kLat = 24, kLon = 48;
    const double pi = std::numbers::pi;
    auto at = [&](int i, int j) {
      const double th = pi * i / kLat, ph = 2 * pi * j / kLon;
      return glm::vec3(static_cast<float>(std::sin(th) * std::cos(ph)), static_cast<float>(std::sin(th) * std::sin(ph)),
                       static_cast<float>(std::cos(th)));
    };
    auto tri = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c) {
      for (const glm::vec3& p : {a, b, c}) m->positions.push_back(p), m->normals.push_back(glm::normalize(p));
    };
    for (int i = 0; i < kLat; ++i)
      for (int j = 0; j < kLon; ++j) {
        // θ grows southwards and φ eastwards: (i, j), (i+1, j), (i+1, j+1) turns counter-clockwise seen from outside.
        if (i > 0) tri(at(i, j), at(i + 1, j), at(i, j + 1));
        if (i + 1 < kLat) tri(at(i, j + 1), at(i + 1, j), at(i + 1, j + 1));
      }
    return m;
  }();
  return mesh;
}

std::shared_ptr<const SurfaceMesh> unit_square_mesh() {
  static const std::shared_ptr<const SurfaceMesh> mesh = [] {
    auto m = std::make_shared<SurfaceMesh>();
    for (const glm::vec2 p : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, -1), glm::vec2(1, 1),
                              glm::vec2(-1, 1)}) {
      m->positions.push_back({p, 0.0f});
      m->normals.push_back({0.0f, 0.0f, 1.0f});
    }
    return m;
  }();
  return mesh;
}

SurfaceItem rectangle(const glm::dvec3& c, const glm::dvec3& u, const glm::dvec3& v, const Color& color) {
  const glm::dvec3 n = glm::normalize(glm::cross(u, v));
  glm::dmat4 model(1.0);
  model[0] = glm::dvec4(u, 0), model[1] = glm::dvec4(v, 0), model[2] = glm::dvec4(n, 0), model[3] = glm::dvec4(c, 1);
  return {unit_square_mesh(), model, color};
}

SurfaceItem ellipsoid(const glm::dvec3& c, const glm::dmat3& axes, const glm::dvec3& semi_axes, const Color& color) {
  glm::dmat4 model(1.0);
  for (int i = 0; i < 3; ++i) model[i] = glm::dvec4(axes[i] * semi_axes[i], 0);
  model[3] = glm::dvec4(c, 1);
  return {unit_sphere_mesh(), model, color};
}

}  // namespace tumble::viz
