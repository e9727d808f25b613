// Where views land in the frame and how their cameras project (GL-free).
#include <gtest/gtest.h>

#include "compose/view_layout.hpp"

namespace tumble::compose {
namespace {

TEST(ViewLayout, CellsTileTheFrameWithSeparators) {
  // 5 views on 3 columns -> 2 rows.
  const PixelRect a = view_rect(0, 5, 3, 300, 200);
  const PixelRect b = view_rect(1, 5, 3, 300, 200);
  const PixelRect d = view_rect(3, 5, 3, 300, 200);
  EXPECT_EQ(a.x, 0);
  EXPECT_EQ(a.width, 100);
  EXPECT_EQ(a.height, 100);
  EXPECT_EQ(b.x, 101);  // 1 px separator
  EXPECT_EQ(b.width, 99);
  EXPECT_EQ(d.y, 101);
  EXPECT_EQ(d.x, 0);
}

TEST(ViewLayout, SingleViewIsWholeFrame) {
  const PixelRect r = view_rect(0, 1, 1, 160, 120);
  EXPECT_EQ(r.x, 0);
  EXPECT_EQ(r.y, 0);
  EXPECT_EQ(r.width, 160);
  EXPECT_EQ(r.height, 120);
}

TEST(ViewLayout, CameraTargetProjectsToViewCentre) {
  viz::Camera cam;
  const PixelRect r{10, 20, 200, 100};
  const glm::vec2 p = project_to_pixel(cam, r, cam.target);
  EXPECT_NEAR(p.x, 110.0f, 1e-3);
  EXPECT_NEAR(p.y, 70.0f, 1e-3);
  // +z (camera up) appears above the centre, i.e. smaller y.
  EXPECT_LT(project_to_pixel(cam, r, cam.target + glm::dvec3(0, 0, 0.5)).y, p.y);
}

}  // namespace
}  // namespace tumble::compose
