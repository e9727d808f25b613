// An axis pointing at the viewer is marked ⊙ (a ring round its tip in the
// picture plane); one seen at a slant is not, and between the two the ring fades.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "viz/end_on_mark.hpp"
#include "viz/palette.hpp"

namespace tumble::viz {
namespace {

// A view of the unit sphere from `deg` off +e₃ towards +e₁, +e₂ up.
View looking(double deg) {
  View v;
  const double a = deg * std::numbers::pi / 180;
  v.camera.position = 14.0 * glm::dvec3(std::sin(a), 0, std::cos(a));
  v.camera.target = glm::dvec3(0);
  v.camera.up = glm::dvec3(0, 1, 0);
  add_end_on_marks(v, 1.22, 0.05);
  return v;
}

TEST(EndOnMark, AnAxisAtTheViewerIsRingedInThePicturePlane) {
  const View v = looking(0);
  ASSERT_EQ(v.polylines.size(), 1u);  // +e₃ only: −e₃ points away, e₁ and e₂ lie across the view
  const PolylineItem& ring = v.polylines[0];
  EXPECT_EQ(ring.name, "end_on_e3");
  EXPECT_EQ(glm::vec3(ring.color), glm::vec3(color_of(Meaning::axis3)));
  EXPECT_FLOAT_EQ(ring.color.a, 1.0f);
  for (const glm::dvec3& p : ring.points) {
    EXPECT_NEAR(glm::length(p - glm::dvec3(0, 0, 1.22)), 0.05, 1e-12);
    EXPECT_NEAR(p.z, 1.22, 1e-12);  // across the line of sight
  }
}

TEST(EndOnMark, ASlantedAxisHasNoneAndTheRingFadesBetween) {
  EXPECT_TRUE(looking(32).polylines.empty());  // the lesson's end view: e₃ 32° off the line of sight
  EXPECT_FLOAT_EQ(looking(kEndOnDeg - 1).polylines.at(0).color.a, 1.0f);
  const float half = looking(0.5 * (kEndOnDeg + kEndOnFadeDeg)).polylines.at(0).color.a;
  EXPECT_GT(half, 0.2f);
  EXPECT_LT(half, 0.8f);
}

}  // namespace
}  // namespace tumble::viz
