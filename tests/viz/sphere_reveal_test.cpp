// The momentum sphere built up in order (GL-free): the sphere with Π, then
// the energy ellipsoid, then the level curves with Π's whole polhode, then the
// separatrix and its saddles; the ellipsoid fades out after unless the view keeps it.
#include <gtest/gtest.h>

#include "viz/momentum_sphere.hpp"
#include "viz/palette.hpp"
#include "viz/sphere_camera.hpp"
#include "viz/sphere_reveal.hpp"

namespace tumble::viz {
namespace {

const Eigen::Vector3d kI(0.0197, 0.0366, 0.0547);  // the T-handle's moments, kg·m²
const std::array<double, 4> kSteps{2, 3, 2, 4};     // video s: sphere, ellipsoid, curves, separatrix

// What a frame of the lesson's sphere draws `since` video s into the build-up (its path a trail, not yet begun).
View drawn(double since) {
  const Eigen::Vector3d pi = kI.cwiseProduct(Eigen::Vector3d(0.5, 8.0, 0.35));
  MomentumSphereInput in{kI, pi, {}, pi.cwiseAbs2().cwiseQuotient(kI).sum()};
  in.camera = textbook_camera(kI, pi);
  in.trail = true;
  in.energy_ellipsoid = false;  // the lesson's view: no ellipsoid but in the build-up
  in.reveal = sphere_reveal(since, kSteps, in.energy_ellipsoid);
  if (in.reveal.ellipsoid) in.energy_ellipsoid = true, in.ellipsoid_alpha = kEnergyEllipsoidAlpha * *in.reveal.ellipsoid;
  View v;
  build_momentum_sphere(v, in);
  return v;
}

struct Seen {
  int grey = 0, polhode = 0, separatrix = 0, saddles = 0, ellipsoid = 0, dot = 0;
};
Seen seen(const View& v) {
  Seen s;
  for (const PolylineItem& p : v.polylines) {
    s.grey += p.name.empty() && glm::vec3(p.color) == glm::vec3(color_of(Meaning::other_levels));
    s.polhode += p.name == "polhode";
    s.separatrix += p.name == "separatrix";
  }
  for (const PointItem& p : v.points) {
    s.saddles += p.name == "saddle_+e2" || p.name == "saddle_-e2";
    s.dot += p.name == "momentum_point";
  }
  s.ellipsoid = static_cast<int>(v.surfaces.size());
  return s;
}

TEST(SphereReveal, StepsComeInOrderEachWithWhatItNames) {
  const Seen sphere = seen(drawn(1.0)), ellipsoid = seen(drawn(3.5)), curves = seen(drawn(6.0)), sep = seen(drawn(9.0));
  // Step 1: the sphere, its axes and Π; nothing else.
  EXPECT_EQ(sphere.dot, 1);
  EXPECT_EQ(sphere.grey + sphere.polhode + sphere.separatrix + sphere.saddles + sphere.ellipsoid, 0);
  // Step 2: the energy ellipsoid joins.
  EXPECT_EQ(ellipsoid.ellipsoid, 1);
  EXPECT_EQ(ellipsoid.grey + ellipsoid.polhode + ellipsoid.separatrix + ellipsoid.saddles, 0);
  // Step 3: the curves where the two meet, Π's own whole polhode among them (before Π has a trail).
  EXPECT_EQ(curves.ellipsoid, 1);
  EXPECT_GT(curves.grey, 0);
  EXPECT_EQ(curves.polhode, 1);
  EXPECT_EQ(curves.separatrix + curves.saddles, 0);
  // Step 4: the separatrix and its saddles last.
  EXPECT_GT(sep.separatrix, 0);
  EXPECT_EQ(sep.saddles, 2);
  EXPECT_EQ(sep.polhode, 1);
}

TEST(SphereReveal, AfterTheBuildUpTheViewIsItsOwnAgain) {
  // The ellipsoid fades in over kRevealFadeSeconds at its step and out after the last step.
  EXPECT_FALSE(sphere_reveal(-1, kSteps).curves);
  EXPECT_FLOAT_EQ(*sphere_reveal(1.0, kSteps).ellipsoid, 0);
  EXPECT_NEAR(*sphere_reveal(2 + 0.5 * kRevealFadeSeconds, kSteps).ellipsoid, 0.5, 1e-6);
  EXPECT_FLOAT_EQ(*sphere_reveal(10.9, kSteps).ellipsoid, 1);
  EXPECT_NEAR(*sphere_reveal(11 + 0.5 * kRevealFadeSeconds, kSteps).ellipsoid, 0.5, 1e-6);
  EXPECT_FALSE(sphere_reveal(11 + kRevealFadeSeconds, kSteps).ellipsoid);
  // A view that draws its ellipsoid keeps it at full strength.
  EXPECT_FLOAT_EQ(*sphere_reveal(10.9, kSteps, true).ellipsoid, 1);
  EXPECT_FALSE(sphere_reveal(11.1, kSteps, true).ellipsoid);
  // Past the end: the trail alone (no whole polhode), no ellipsoid, every curve.
  const Seen after = seen(drawn(20));
  EXPECT_EQ(after.ellipsoid, 0);
  EXPECT_EQ(after.polhode, 0);  // the trail has fewer than two points at t = 0
  EXPECT_GT(after.grey, 0);
  EXPECT_EQ(after.saddles, 2);
  // A default reveal (no build-up) draws everything, as before.
  const SphereReveal all;
  EXPECT_TRUE(all.curves && all.separatrix && !all.ellipsoid && !all.whole_polhode);
}

}  // namespace
}  // namespace tumble::viz
