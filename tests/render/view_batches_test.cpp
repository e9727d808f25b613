// GL-free parts of the renderer: batching.
#include <gtest/gtest.h>

#include "render/view_batches.hpp"

namespace tumble::render {
namespace {

TEST(ViewBatches, ArrowSplitsIntoShaftAndHead) {
  viz::View v;
  v.arrows.push_back({{1, 2, 3}, {0, 0, 2}, 0.05, {1, 0, 0, 1}});
  v.arrows.push_back({{0, 0, 0}, {0, 0, 0}, 0.05, {1, 0, 0, 1}});  // degenerate: skipped
  const ViewBatches b = build_view_batches(v);
  ASSERT_EQ(b.arrow_shafts.size(), 1u);
  ASSERT_EQ(b.arrow_heads.size(), 1u);
  // Shaft starts at the origin, head tip reaches origin + vector.
  const glm::vec4 shaft_base = b.arrow_shafts[0].model * glm::vec4(0, 0, 0, 1);
  const glm::vec4 tip = b.arrow_heads[0].model * glm::vec4(0, 0, 1, 1);
  EXPECT_NEAR(shaft_base.z, 3.0f, 1e-6);
  EXPECT_NEAR(tip.x, 1.0f, 1e-6);
  EXPECT_NEAR(tip.z, 5.0f, 1e-6);
}

// An arrow keeps its round cross-section whatever way it points, along the
// x axis too (where the helper vector for its frame must not be x itself).
TEST(ViewBatches, ArrowsAlongEveryAxisKeepTheirRadius) {
  for (const glm::dvec3& d : {glm::dvec3(2, 0, 0), glm::dvec3(-2, 0, 0), glm::dvec3(0, 2, 0), glm::dvec3(0, 0, 2),
                              glm::dvec3(1.9, 0.3, 0.1)}) {
    viz::View v;
    v.arrows.push_back({{0, 0, 0}, d, 0.05, {1, 0, 0, 1}});
    const ViewBatches b = build_view_batches(v);
    ASSERT_EQ(b.arrow_shafts.size(), 1u);
    const glm::mat4& m = b.arrow_shafts[0].model;
    for (int c = 0; c < 2; ++c) {  // the radial columns: radius long, across the arrow
      const glm::vec3 r(m[c]);
      EXPECT_NEAR(glm::length(r), 0.05f, 1e-6f) << "direction " << d.x << " " << d.y << " " << d.z;
      EXPECT_NEAR(glm::dot(r, glm::vec3(glm::normalize(d))), 0.0f, 1e-6f);
    }
  }
}

TEST(ViewBatches, BoxesSortedFarToNearWithTwelveEdges) {
  viz::View v;
  v.camera.position = {0, -10, 0};
  const glm::dmat3 eye3(1.0);
  v.boxes.push_back({{0, -5, 0}, eye3, {1, 1, 1}, {1, 0, 0, 0.3f}, {0, 0, 0, 1}});  // near
  v.boxes.push_back({{0, 5, 0}, eye3, {1, 2, 3}, {0, 1, 0, 0.3f}, {0, 0, 0, 1}});   // far
  const ViewBatches b = build_view_batches(v);
  ASSERT_EQ(b.boxes.size(), 2u);
  EXPECT_FLOAT_EQ(b.boxes[0].color.g, 1.0f);  // far one first
  EXPECT_EQ(b.box_edges.size(), 2u * 12u * 2u);
  // The far box's unit-cube corner (1,1,1) maps to centre + half extents.
  const glm::vec4 c = b.boxes[0].model * glm::vec4(1, 1, 1, 1);
  EXPECT_NEAR(c.x, 1.0f, 1e-6);
  EXPECT_NEAR(c.y, 7.0f, 1e-6);
  EXPECT_NEAR(c.z, 3.0f, 1e-6);
}

TEST(ViewBatches, PolylineFadesOldestToNewest) {
  viz::View v;
  v.polylines.push_back({{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {0, 0, 1, 0.8f}, 2.0f});
  const ViewBatches b = build_view_batches(v);
  ASSERT_EQ(b.polylines.size(), 1u);
  const auto& s = b.polylines[0].strip;
  ASSERT_EQ(s.size(), 3u);
  EXPECT_LT(s[0].color.a, s[1].color.a);
  EXPECT_LT(s[1].color.a, s[2].color.a);
  EXPECT_FLOAT_EQ(s[2].color.a, 0.8f);
}

}  // namespace
}  // namespace tumble::render
