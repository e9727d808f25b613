// The physics of the explanatory views: Poinsot's construction, the momentum
// sphere's polhodes and separatrix, and the strip chart's and captions' layout.
#include <cmath>

#include <gtest/gtest.h>

#include "core/dynamics.hpp"
#include "core/mass_properties.hpp"
#include "core/propagator.hpp"
#include "viz/captions.hpp"
#include "viz/momentum_sphere.hpp"
#include "viz/poinsot.hpp"
#include "viz/scene_view.hpp"
#include "viz/strip_chart.hpp"

namespace tumble::viz {
namespace {

// A T-handle-like body spun near its intermediate axis, stepped by the closed form.
struct Tumbler {
  ParticleCloud cloud = make_box({3.0, 1.0, 0.4}, {6, 3, 2}, 2.0);
  RigidBodyModel model = make_model("t", compute_mass_properties(cloud, "t"), ForceSet{});
  BodyState s0;
  Tumbler() {
    InitialConditions ic;
    ic.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, -2, 0.5).normalized()));
    ic.omega = {0.05, 6.0, 0.08};  // cloud axes: y is the intermediate one for this box
    s0 = make_state(model, ic);
  }
  std::vector<BodyState> run(int n, double dt) const {
    Propagator p(model, s0, {Method::exact, 1e-3});
    std::vector<BodyState> out;
    for (int i = 0; i <= n; ++i) out.push_back(p.advance_to(i * dt));
    return out;
  }
};

double rel(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); }

TEST(Poinsot, EllipsoidTouchesTheInvariablePlaneAtOmegasTip) {
  const Tumbler b;
  const double two_E0 = 2 * kinetic_energy(b.model, b.s0), L0 = b.s0.L.norm();
  for (const BodyState& s : b.run(60, 0.05)) {
    const PoinsotGeometry p = poinsot_geometry(s.q, b.model.inertia, s.L);
    const Eigen::Vector3d w = omega_world(b.model, s);
    EXPECT_LT((p.contact - w).norm(), 1e-12 * w.norm());
    // On the ellipsoid: Σ (e_i·ω / a_i)² = 1.
    const Eigen::Vector3d local = p.axes.transpose() * p.contact;
    EXPECT_NEAR(local.cwiseQuotient(p.semi_axes).squaredNorm(), 1.0, 1e-12);
    // The ellipsoid's normal there (∝ J ω, J = R diag(I) Rᵀ) is the plane's normal L̂.
    const Eigen::Vector3d grad = p.axes * b.model.inertia.cwiseProduct(local);
    EXPECT_LT((grad.normalized() - p.normal).norm(), 1e-12);
    // On the plane, whose distance from the origin along L is the constant 2E/|L|.
    EXPECT_NEAR(p.contact.dot(p.normal), p.plane_distance, 1e-12 * p.plane_distance);
    EXPECT_LT(rel(p.plane_distance, two_E0 / L0), 1e-9);
    EXPECT_LT((p.normal - b.s0.L.normalized()).norm(), 1e-9);
  }
}

TEST(Poinsot, ViewDrawsOmegaToTheContactPointAndTheHerpolhodeOnThePlane) {
  const Tumbler b;
  const auto states = b.run(40, 0.05);
  PoinsotInput in{states.back().q, b.model.inertia, states.back().L, {}, {}, ""};
  for (const BodyState& s : states) {
    in.omega_principal_history.push_back(omega_principal(b.model, s));
    in.omega_world_history.push_back(omega_world(b.model, s));
  }
  View v;
  build_poinsot(v, in);
  const PoinsotGeometry p = poinsot_geometry(in.q, in.inertia, in.L);
  const double scale = 1.0 / p.semi_axes.maxCoeff();
  // The dot sits on the contact point; the herpolhode (last polyline) lies in the plane.
  const glm::dvec3 dot = v.points.back().position;
  EXPECT_LT((Eigen::Vector3d(dot.x, dot.y, dot.z) - p.contact * scale).norm(), 1e-12);
  const PolylineItem& herpolhode = v.polylines.back();
  ASSERT_EQ(herpolhode.points.size(), states.size());
  for (const glm::dvec3& x : herpolhode.points)
    EXPECT_NEAR(Eigen::Vector3d(x.x, x.y, x.z).dot(p.normal), p.plane_distance * scale, 1e-9);
  bool omega_arrow = false;
  for (const ArrowItem& a : v.arrows)
    if (a.color == kOmegaColor) omega_arrow = glm::length(a.vector - dot) < 1e-12;
  EXPECT_TRUE(omega_arrow);
}

TEST(MomentumSphere, DotStaysOnTheSphereAndTheEnergyEllipsoid) {
  const Tumbler b;
  const Eigen::Vector3d I = b.model.inertia;
  const double L = b.s0.L.norm(), two_E = 2 * kinetic_energy(b.model, b.s0);
  for (const BodyState& s : b.run(80, 0.05)) {
    MomentumSphereInput in{I, momentum_body(s), {}, two_E, ""};
    View v;
    build_momentum_sphere(v, in);
    const glm::dvec3 d = v.points.back().position;  // in units of |L|
    const Eigen::Vector3d pi = L * Eigen::Vector3d(d.x, d.y, d.z);
    EXPECT_NEAR(pi.norm() / L, 1.0, 1e-9);
    EXPECT_NEAR(pi.cwiseAbs2().cwiseQuotient(I).sum() / two_E, 1.0, 1e-9);
  }
}

TEST(MomentumSphere, PolhodesLieOnBothSurfaces) {
  const Eigen::Vector3d I(1, 2, 3);
  const double L = 2.0;
  for (double two_E : {L * L / 2.9, L * L / 2.5, L * L / 1.5, L * L / 1.1}) {
    const auto curves = polhodes(I, L, two_E, 64);
    ASSERT_EQ(curves.size(), 2u) << two_E;
    for (const auto& c : curves)
      for (const Eigen::Vector3d& p : c) {
        EXPECT_NEAR(p.norm(), L, 1e-12);
        EXPECT_NEAR(p.cwiseAbs2().cwiseQuotient(I).sum(), two_E, 1e-12);
      }
  }
  EXPECT_TRUE(polhodes(I, L, L * L / 0.9, 16).empty());  // above L²/I1: no such motion
}

TEST(MomentumSphere, SeparatrixPassesThroughTheIntermediateAxis) {
  const Eigen::Vector3d I(1, 2, 3);
  const double L = 2.0;
  const auto sep = separatrix(I, L, 64);
  ASSERT_EQ(sep.size(), 2u);
  for (const auto& circle : sep) {
    bool plus = false, minus = false;
    for (const Eigen::Vector3d& p : circle) {
      EXPECT_NEAR(p.norm(), L, 1e-12);
      EXPECT_NEAR(p.cwiseAbs2().cwiseQuotient(I).sum(), L * L / I[1], 1e-12);  // the level 2E = L²/I2
      plus = plus || (p - Eigen::Vector3d(0, L, 0)).norm() < 1e-12;
      minus = minus || (p - Eigen::Vector3d(0, -L, 0)).norm() < 1e-12;
    }
    EXPECT_TRUE(plus && minus);
  }
  // The view draws it: a polyline through +e2 (units of |L|) in the separatrix's colour, not e1's.
  View v;
  build_momentum_sphere(v, {I, Eigen::Vector3d(0.1, 1.9, 0.2), {}, 2.0, ""});
  int through = 0;
  for (const PolylineItem& p : v.polylines)
    if (p.name == "separatrix")
      for (const glm::dvec3& x : p.points) {
        through += glm::length(x - glm::dvec3(0, 1, 0)) < 1e-12;
        EXPECT_EQ(p.color, color_of(Meaning::separatrix, p.color.a));
        EXPECT_NE(glm::vec3(p.color), glm::vec3(kAxisColors[0]));
      }
  EXPECT_EQ(through, 2);
}

TEST(StripChart, SeriesAndPlayheadLandOnTheChartMap) {
  StripChartInput in;
  in.times = {0, 1, 2};
  in.series = {{"wbx", {0.0, 1.0, -1.0}, {1, 0, 0, 1}}};
  in.t0 = 0, in.t1 = 4, in.lo = -2, in.hi = 2, in.playhead = 2;
  View v;
  build_strip_chart(v, in, 400, 200, 12.0f);
  const ChartMap m(in, 400, 200, 12.0f);
  bool series = false, playhead = false;
  for (const PolylineItem& p : v.polylines) {
    EXPECT_FALSE(p.fade);
    if (p.points.size() == 3) series = p.points[1] == m.at(1, 1.0) && p.points[2] == m.at(2, -1.0);
    if (p.points.size() == 2 && p.points[0] == m.at(2, -2) && p.points[1] == m.at(2, 2)) playhead = true;
  }
  EXPECT_TRUE(series);
  EXPECT_TRUE(playhead);
  // The chart's corners project (orthographic camera) to the pixels the labels use.
  glm::vec2 px;
  ASSERT_TRUE(project_to_viewport(v.camera, 400, 200, m.at(0, 2), px));
  EXPECT_NEAR(px.x, m.pixel(m.at(0, 2)).x, 1e-3);
  EXPECT_NEAR(px.y, m.pixel(m.at(0, 2)).y, 1e-3);
  EXPECT_GT(px.x, 0);
  EXPECT_LT(px.x, 400);
}

TEST(Captions, FadeInHoldFadeOut) {
  EXPECT_EQ(fade_alpha(0.9, 1, 3), 0.0f);
  EXPECT_NEAR(fade_alpha(1.2, 1, 3), 0.5f, 1e-6);
  EXPECT_EQ(fade_alpha(2.0, 1, 3), 1.0f);
  EXPECT_NEAR(fade_alpha(2.9, 1, 3), 0.25f, 1e-6);
  EXPECT_EQ(fade_alpha(3.1, 1, 3), 0.0f);
  EXPECT_NEAR(fade_alpha(1.1, 1, 1.8), 0.5f, 1e-6);  // short span: fades take a quarter each
  const TextItem c = caption_item("hello", 0.5f, 1280, 720);
  EXPECT_EQ(c.color.a, 0.5f);
  EXPECT_GT(c.position_px.y, 600.0f);
}

}  // namespace
}  // namespace tumble::viz
