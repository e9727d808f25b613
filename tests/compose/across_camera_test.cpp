// A camera across L: L up in the picture, or turned by `roll` (L along a wide picture).
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "compose/world_views.hpp"

namespace tumble::compose {
namespace {

struct Picture {
  glm::dvec3 right, up;
};

Picture picture_axes(const viz::Camera& c) {
  const glm::dvec3 forward = glm::normalize(c.target - c.position);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, c.up));
  return {right, glm::cross(right, forward)};
}

TEST(AcrossCamera, LIsUpWithoutRollAndPointsRightWithRoll90) {
  const Eigen::Vector3d L(0.3, 2.0, -0.4), target(1, 2, 3);
  const glm::dvec3 l = glm::normalize(glm::dvec3(L.x(), L.y(), L.z()));
  const Picture plain = picture_axes(across_camera(target, L, +1, -32, 0, 5, 35));
  EXPECT_NEAR(glm::dot(l, plain.up), 1.0, 1e-9);
  const Picture rolled = picture_axes(across_camera(target, L, +1, -32, 0, 5, 35, 90));
  EXPECT_NEAR(glm::dot(l, rolled.right), 1.0, 1e-9);
  EXPECT_NEAR(glm::dot(l, rolled.up), 0.0, 1e-9);
  // The roll turns the picture only: the camera stays where it was.
  EXPECT_NEAR(glm::length(across_camera(target, L, +1, -32, 0, 5, 35, 90).position -
                          across_camera(target, L, +1, -32, 0, 5, 35).position), 0.0, 1e-12);
  const Picture back = picture_axes(across_camera(target, L, +1, -32, 0, 5, 35, -90));
  EXPECT_NEAR(glm::dot(l, back.right), -1.0, 1e-9);
}

}  // namespace
}  // namespace tumble::compose
