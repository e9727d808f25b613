#include "test_scenes.hpp"

#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

namespace tumble::render::test {

viz::DrawList axis_arrows() {
  viz::DrawList dl;
  viz::View v;
  v.camera.position = {2.2, -3.2, 1.8};
  v.camera.target = {0.2, 0.2, 0.2};
  const viz::Color colors[3] = {{1, 0, 0, 1}, {0, 0.8f, 0, 1}, {0, 0, 1, 1}};
  for (int axis = 0; axis < 3; ++axis) {
    glm::dvec3 dir(0);
    dir[axis] = 1.0;
    v.arrows.push_back({glm::dvec3(0), dir, 0.05, colors[axis]});
  }
  dl.views.push_back(v);
  return dl;
}

viz::DrawList showcase() {
  viz::DrawList dl;
  dl.columns = 2;
  const char* labels[4] = {"RK4", "Lie–Poisson (ω)", "implicit midpoint", "exact"};
  for (int i = 0; i < 4; ++i) {
    viz::View v;
    // Each view's name in its top-left corner, as the frame layout puts a view's title.
    v.texts.push_back({labels[i], {7, 4}, 13, {0.13f, 0.14f, 0.18f, 0.95f}, "view_title"});
    v.camera.position = {3.0, -4.5, 2.4};
    const double angle = 0.5 * i;
    const glm::dmat3 rot = glm::dmat3(glm::rotate(glm::dmat4(1), angle, glm::dvec3(0.3, 0.5, 1)));
    v.boxes.push_back({{0, 0, 0.2}, rot, {0.9, 0.5, 0.25}, {0.30f, 0.55f, 0.90f, 0.35f},
                       {0.10f, 0.15f, 0.25f, 0.9f}});
    const viz::Color axis_colors[3] = {{0.85f, 0.15f, 0.15f, 1}, {0.15f, 0.65f, 0.2f, 1},
                                       {0.15f, 0.3f, 0.9f, 1}};
    for (int a = 0; a < 3; ++a) {
      v.arrows.push_back({{0, 0, 0.2}, rot[a] * 1.3, 0.03, axis_colors[a]});
    }
    v.arrows.push_back({{0, 0, 0.2}, {0.4, -0.3, 1.1}, 0.04, {0.95f, 0.6f, 0.1f, 1}});
    for (int k = 0; k < 12; ++k) {
      const double t = k / 12.0 * 6.2831853;
      v.points.push_back({{1.4 * std::cos(t), 1.4 * std::sin(t), 0.2 + 0.2 * std::sin(3 * t)},
                          0.05, {0.5f, 0.5f, 0.55f, 1}});
    }
    viz::PolylineItem trail{{}, {0.85f, 0.15f, 0.15f, 1}, 2.5f};
    for (int k = 0; k <= 80; ++k) {
      const double t = k / 80.0 * 4.0;
      trail.points.push_back(
          {1.3 * std::cos(t + angle), 1.3 * std::sin(t + angle), 0.2 + 0.5 * std::sin(2 * t)});
    }
    v.polylines.push_back(trail);
    v.grids.push_back({{0, 0, -0.6}, 0.5, 8, {0.45f, 0.5f, 0.6f, 0.5f}});
    v.texts.push_back({"t = 1.25 s", {8, 150}, 13, {0.2f, 0.2f, 0.25f, 1}});
    dl.views.push_back(v);
  }
  dl.texts.push_back({"tumble showcase", {250, 4}, 16, {0.1f, 0.1f, 0.1f, 1}});
  return dl;
}

}  // namespace tumble::render::test
