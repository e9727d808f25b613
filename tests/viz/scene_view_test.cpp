// The draw list puts box corners and axis tips where the core's state says.
#include <gtest/gtest.h>

#include "core/dynamics.hpp"
#include "core/mass_properties.hpp"
#include "core/particle_cloud.hpp"
#include "viz/particle_set.hpp"
#include "viz/scene_view.hpp"

namespace tumble::viz {
namespace {

struct Fixture {
  ParticleCloud cloud = make_box({2.0, 1.0, 0.5}, {8, 4, 2}, 3.0);
  RigidBodyModel model = make_model("b", compute_mass_properties(cloud, "b"), ForceSet{});
  BodyState state;
  Fixture() {
    InitialConditions ic;
    ic.position = {1, 2, 3};
    ic.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
    state = make_state(model, ic);
  }
};

TEST(SceneView, BoxCornersMatchTransformedCloudExtents) {
  Fixture f;
  View v;
  add_bodies(v, {{&f.model, &f.cloud, f.state}}, DrawOptions{}, nullptr, 0);
  ASSERT_EQ(v.boxes.size(), 1u);
  const BoxItem& b = v.boxes[0];
  // Every particle, transformed by the state, lies inside the drawn box, and the
  // extreme particles touch its faces.
  const Eigen::Quaterniond qc = cloud_orientation(f.model, f.state);
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const Particle& p : f.cloud) {
    const Eigen::Vector3d w = f.state.c + qc * (p.position - f.model.com_cloud);
    const glm::dvec3 local = glm::transpose(b.rotation) * (glm::dvec3(w.x(), w.y(), w.z()) - b.center);
    lo = glm::min(lo, local);
    hi = glm::max(hi, local);
  }
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(lo[i], -b.half_extents[i], 1e-12);
    EXPECT_NEAR(hi[i], b.half_extents[i], 1e-12);
  }
  // Lattice cell centres: full extents 2 - 2/8, 1 - 1/4, 0.5 - 0.5/2 (sorted by moment).
  EXPECT_NEAR(b.half_extents[0], 0.875, 1e-12);
  EXPECT_NEAR(b.half_extents[1], 0.375, 1e-12);
  EXPECT_NEAR(b.half_extents[2], 0.125, 1e-12);
}

TEST(SceneView, ParticleSetIsPlacedWhereTheStateSays) {
  Fixture f;
  BodyLook look;
  look.particles = make_particle_set(f.cloud, {}, float(particle_radius(f.model)));
  DrawOptions opt;
  opt.particles = true;
  View v;
  BodySnapshot snap{&f.model, &f.cloud, f.state};
  snap.look = &look;
  add_bodies(v, {snap}, opt, nullptr, 0);
  EXPECT_TRUE(v.points.empty());  // one shared item, not a point per particle
  ASSERT_EQ(v.particles.size(), 1u);
  EXPECT_EQ(v.particles[0].set, look.particles);
  // Its model matrix maps each cloud position to x_world = c + q_cloud (x - com).
  const Eigen::Quaterniond qc = cloud_orientation(f.model, f.state);
  for (const Particle& p : f.cloud) {
    const Eigen::Vector3d w = f.state.c + qc * (p.position - f.model.com_cloud);
    const glm::dvec3 m = v.particles[0].model * glm::dvec4(p.position.x(), p.position.y(), p.position.z(), 1.0);
    EXPECT_NEAR(glm::length(m - glm::dvec3(w.x(), w.y(), w.z())), 0.0, 1e-12);
  }
  // The whole 8 x 4 x 2 lattice is its shell.
  EXPECT_EQ(look.particles->levels.at(0).positions.size(), f.cloud.size());
}

TEST(SceneView, AxisArrowsStartAtComAndFollowPrincipalAxes) {
  Fixture f;
  View v;
  add_bodies(v, {{&f.model, &f.cloud, f.state}}, DrawOptions{}, nullptr, 0);
  ASSERT_EQ(v.arrows.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    const ArrowItem& a = v.arrows[i];
    EXPECT_NEAR(glm::length(a.origin - glm::dvec3(1, 2, 3)), 0.0, 1e-12);
    const Eigen::Vector3d axis = f.state.q * Eigen::Vector3d::Unit(i);
    const glm::dvec3 dir = glm::normalize(a.vector);
    EXPECT_NEAR(glm::dot(dir, glm::dvec3(axis.x(), axis.y(), axis.z())), 1.0, 1e-12);
    EXPECT_EQ(a.color, kAxisColors[i]);
  }
  // Axis 1 (smallest moment) is the long x edge of this box: its tip is just past the face.
  EXPECT_NEAR(glm::length(v.arrows[0].vector), kAxisOvershoot * 0.875, 1e-12);
}

// arrow_length scales L's line and ω's arrow (both ends), and nothing else.
TEST(SceneView, ArrowLengthScalesLAndOmegaOnly) {
  ParticleCloud cloud = make_box({2.0, 1.0, 0.5}, {8, 4, 2}, 3.0);
  RigidBodyModel model = make_model("b", compute_mass_properties(cloud, "b"), ForceSet{});
  InitialConditions ic;
  ic.omega = {0.3, 1.0, 2.0};
  const BodyState state = make_state(model, ic);
  DrawOptions usual;
  usual.angular_momentum = usual.omega = true;
  DrawOptions shorter = usual;
  shorter.arrow_length = 0.5;
  View a, b;
  add_bodies(a, {{&model, &cloud, state}}, usual, nullptr, 0);
  add_bodies(b, {{&model, &cloud, state}}, shorter, nullptr, 0);
  ASSERT_EQ(a.arrows.size(), 5u);  // three axes, L, ω
  ASSERT_EQ(b.arrows.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) {
    const double k = a.arrows[i].name == "L" || a.arrows[i].name == "omega" ? 0.5 : 1.0;
    EXPECT_NEAR(glm::length(b.arrows[i].vector), k * glm::length(a.arrows[i].vector), 1e-12) << a.arrows[i].name;
    EXPECT_NEAR(glm::length(b.arrows[i].origin - glm::dvec3(0)), k * glm::length(a.arrows[i].origin - glm::dvec3(0)), 1e-12)
        << a.arrows[i].name;
  }
}

// [draw] angle_arc: an arc about the centre of mass from L's direction to ω's,
// its points on one circle, sweeping exactly ∠(ω, L); none without the option.
TEST(SceneView, TheAngleArcRunsFromLToOmega) {
  ParticleCloud cloud = make_box({2.0, 1.0, 0.5}, {8, 4, 2}, 3.0);
  RigidBodyModel model = make_model("b", compute_mass_properties(cloud, "b"), ForceSet{});
  InitialConditions ic;
  ic.position = {1, 2, 3};
  ic.omega = {0.3, 1.0, 2.0};
  const BodyState state = make_state(model, ic);
  DrawOptions opt;
  opt.angular_momentum = opt.omega = true;
  View plain, arc;
  add_bodies(plain, {{&model, &cloud, state}}, opt, nullptr, 0);
  EXPECT_TRUE(plain.polylines.empty());
  opt.angle_arc = true;
  add_bodies(arc, {{&model, &cloud, state}}, opt, nullptr, 0);
  ASSERT_EQ(arc.polylines.size(), 1u);
  const PolylineItem& p = arc.polylines[0];
  EXPECT_EQ(p.name, "angle_arc");
  ASSERT_GE(p.points.size(), 3u);
  const glm::dvec3 c(1, 2, 3);
  const Eigen::Vector3d w = omega_world(model, state);
  const glm::dvec3 L = glm::normalize(glm::dvec3(state.L.x(), state.L.y(), state.L.z()));
  const glm::dvec3 W = glm::normalize(glm::dvec3(w.x(), w.y(), w.z()));
  const double r = glm::length(p.points.front() - c);
  EXPECT_GT(r, 0);
  for (const glm::dvec3& x : p.points) EXPECT_NEAR(glm::length(x - c), r, 1e-9 * r);
  EXPECT_NEAR(glm::dot(glm::normalize(p.points.front() - c), L), 1.0, 1e-12);
  EXPECT_NEAR(glm::dot(glm::normalize(p.points.back() - c), W), 1.0, 1e-12);
  // No arc for a spin about a principal axis (ω along L).
  ic.omega = {0, 0, 2.0};
  View along;
  add_bodies(along, {{&model, &cloud, make_state(model, ic)}}, opt, nullptr, 0);
  EXPECT_TRUE(along.polylines.empty());
}

TEST(SceneView, TrailsKeepOnlyTheWindow) {
  Fixture f;
  TrailRecorder rec;
  for (int k = 0; k <= 10; ++k) {
    BodyState s = f.state;
    s.c.x() += k;
    rec.record(0.1 * k, {{&f.model, nullptr, s}});
  }
  const auto lines = rec.polylines(1.0, 0.35);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].points.size(), 4u);  // t = 0.7, 0.8, 0.9, 1.0
  // Only the chosen axes' tips (the T-handle's stem, e2) leave a trail.
  const auto stem = rec.polylines(1.0, 0.35, {false, true, false});
  ASSERT_EQ(stem.size(), 1u);
  EXPECT_EQ(stem[0].color, kAxisColors[1]);
}

TEST(SceneView, AutoCameraSeesEverything) {
  const Camera c = auto_camera({{0, 0, 0}, {10, 0, 0}}, {1, 1}, 40, 16.0 / 9);
  EXPECT_NEAR(c.target.x, 5.0, 1e-12);
  EXPECT_GT(glm::length(c.position - c.target), 6.0);
}

}  // namespace
}  // namespace tumble::viz

namespace {

TEST(ViewUp, AnUpAlongTheViewFallsBackAndAnyOtherIsKept) {
  tumble::viz::Camera c;
  c.position = {0, 0, 5};
  c.target = {0, 0, 0};
  c.up = {0, 0, 1};  // a camera following a body from straight above
  EXPECT_EQ(tumble::viz::view_up(c), glm::dvec3(0, 1, 0));
  c.position = {0, 3, 0};
  c.up = {0, -1, 0};
  EXPECT_EQ(tumble::viz::view_up(c), glm::dvec3(1, 0, 0));
  c.up = {0.3, 1, 0};
  EXPECT_EQ(tumble::viz::view_up(c), glm::dvec3(0.3, 1, 0));
}

}  // namespace
