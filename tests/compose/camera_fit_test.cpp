// Backing a camera off until the content fits: every point inside the frame
// (within the margins) and beyond the near plane.
#include <gtest/gtest.h>

#include "compose/camera_fit.hpp"

namespace tumble::compose {
namespace {

viz::Camera looking_down_z(double distance, double near_m) {
  viz::Camera c;
  c.position = {0, 0, distance};
  c.target = {0, 0, 0};
  c.up = {0, 1, 0};
  c.near_m = near_m;
  return c;
}

// A point on the axis between the camera and its near plane is in the
// frame's middle yet would be clipped away: the camera backs off until it is
// past the near plane (distance 5·f − 4.5 ≥ 1, so f ≥ 1.1), and no further than needed.
TEST(CameraFit, APointBeforeTheNearPlaneMakesTheCameraBackOff) {
  const Shot s{looking_down_z(5, 1), {{0, 0, 0}, {0, 0, 4.5}}};
  const double f = backoff({s}, 1.0, Margins(0.1));
  EXPECT_GE(f, 1.1 - 1e-6);
  EXPECT_LT(f, 1.1 + 1e-3);
  const Shot beyond{looking_down_z(5, 1), {{0, 0, 0}, {0, 0, 3.5}}};  // 1.5 m away: already fits
  EXPECT_EQ(backoff({beyond}, 1.0, Margins(0.1)), 1.0);
}

// Height counts as much as width: a tall point set backs off by its height.
TEST(CameraFit, TheFrameHeightLimitsAsMuchAsItsWidth) {
  const Shot wide{looking_down_z(5, 0.05), {{3, 0, 0}, {-3, 0, 0}}};
  const Shot tall{looking_down_z(5, 0.05), {{0, 3, 0}, {0, -3, 0}}};
  const double fw = backoff({wide}, 2.0, Margins(0.1)), ft = backoff({tall}, 2.0, Margins(0.1));
  EXPECT_GT(ft, 1.5 * fw) << "a 2:1 frame fits a tall set only from further away";
}

// Content reaching further up than down (L's line above a body): the camera
// moves up with its target until the content is centred, and then comes
// closer than it could looking at the middle (the fit is set by 2 m each way, not 3).
TEST(CameraFit, CentringLeavesAsMuchRoomOnEitherSide) {
  const viz::Camera cam = looking_down_z(10, 0.05);
  std::vector<Shot> shots{{cam, {{0, 3, 0}, {0, -1, 0}, {1, 0, 0}}}};
  const double f0 = backoff(shots, 1.0, Margins(0.1), 0.1);
  const viz::Camera c = centred(cam, shots, 1.0, f0);
  EXPECT_NEAR(c.target.y, 1.0, 1e-3);
  EXPECT_NEAR(c.position.y, 1.0, 1e-3);
  EXPECT_EQ(c.position.z, cam.position.z);
  shots[0].camera = c;
  EXPECT_NEAR(backoff(shots, 1.0, Margins(0.1), 0.1) / f0, 2.0 / 3.0, 1e-3);
}

}  // namespace
}  // namespace tumble::compose
