// The physics of the explanatory views: Poinsot's construction, the momentum
// sphere's polhodes and separatrix, and the strip chart's and captions' layout.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "core/dynamics.hpp"
#include "core/mass_properties.hpp"
#include "core/propagator.hpp"
#include "viz/captions.hpp"
#include "viz/key.hpp"
#include "viz/momentum_sphere.hpp"
#include "viz/poinsot.hpp"
#include "viz/scene_view.hpp"
#include "viz/strip_chart.hpp"
#include "viz/text_layout.hpp"

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

// The Poinsot view's input at the last state, with ω's history over `states`.
PoinsotInput poinsot_input(const Tumbler& b, const std::vector<BodyState>& states) {
  PoinsotInput in{states.back().q, b.model.inertia, states.back().L, {}, {}};
  for (const BodyState& s : states) {
    in.omega_principal_history.push_back(omega_principal(b.model, s));
    in.omega_world_history.push_back(omega_world(b.model, s));
  }
  return in;
}

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
  PoinsotInput in = poinsot_input(b, states);
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
    EXPECT_NEAR(Eigen::Vector3d(x.x, x.y, x.z).dot(p.normal), p.plane_distance * scale - kHerpolhodeLift, 1e-9);
  // The dot is seen from the back of a hall (5 % of the largest semi-axis and
  // more); the herpolhode, thinner than the polhode, fades with age, so loops
  // laid over loops do not fill a ring.
  EXPECT_GE(v.points.back().radius, 0.05);
  const auto polhode = std::find_if(v.polylines.begin(), v.polylines.end(), [](const PolylineItem& l) { return l.name == "polhode"; });
  ASSERT_NE(polhode, v.polylines.end());
  EXPECT_LT(herpolhode.width_px, 0.7f * polhode->width_px);
  EXPECT_TRUE(herpolhode.fade);
  bool omega_arrow = false;
  for (const ArrowItem& a : v.arrows)
    if (a.color == kOmegaColor) omega_arrow = glm::length(a.vector - dot) < 1e-12;
  EXPECT_TRUE(omega_arrow);
}

// A shaded translucent ellipsoid on an opaque plane, seen from
// well above the plane, with its curves named inside the view.
TEST(Poinsot, TranslucentEllipsoidOnOpaquePlaneSeenFromAboveWithNames) {
  const Tumbler b;
  const auto states = b.run(40, 0.05);
  PoinsotInput in = poinsot_input(b, states);
  in.width_px = 640, in.height_px = 360;
  View v;
  build_poinsot(v, in);
  const PoinsotGeometry p = poinsot_geometry(in.q, in.inertia, in.L);
  const double scale = 1.0 / p.semi_axes.maxCoeff();
  ASSERT_EQ(v.surfaces.size(), 2u);
  const SurfaceItem &ellipsoid = v.surfaces[0], &plane = v.surfaces[1];
  EXPECT_LT(ellipsoid.color.a, 0.6f);
  EXPECT_EQ(plane.color.a, 1.0f);
  // The ellipsoid's model maps the unit sphere onto it: the contact point is on it.
  const Eigen::Vector3d touch = p.contact * scale;
  const glm::dvec4 unit = glm::inverse(ellipsoid.model) * glm::dvec4(touch.x(), touch.y(), touch.z(), 1);
  EXPECT_NEAR(glm::length(glm::dvec3(unit)), 1.0, 1e-9);
  // The plane's centre is the foot of L, its normal L̂.
  const glm::dvec3 n = glm::normalize(glm::dvec3(plane.model[2]));
  EXPECT_LT(glm::length(n - glm::dvec3(p.normal.x(), p.normal.y(), p.normal.z())), 1e-12);
  EXPECT_NEAR(glm::dot(glm::dvec3(plane.model[3]), n), p.plane_distance * scale, 1e-12);
  // The camera looks down on the plane from at least 30° above it.
  const glm::dvec3 eye = glm::normalize(v.camera.position - v.camera.target);
  EXPECT_GT(glm::dot(eye, -n), std::sin(30.0 * 3.14159265 / 180));
  // Its key names the arrows, the two dots and the ellipsoid (the layout draws it beside the
  // view); the plane and the two curves are named on the picture, inside the view.
  const std::vector<KeyEntry> key = poinsot_key();
  for (const std::string name : {"L:", "ω:", "contact point", "polhode's start", "inertia ellipsoid"})
    EXPECT_TRUE(std::any_of(key.begin(), key.end(), [&](const KeyEntry& e) { return e.text.rfind(name, 0) == 0; }))
        << name;
  EXPECT_EQ(key.size(), 6u);
  for (const std::string name : {"polhode", "herpolhode", "invariable plane"}) {
    const auto t = std::find_if(v.texts.begin(), v.texts.end(), [&](const TextItem& x) { return x.text == name; });
    ASSERT_NE(t, v.texts.end()) << name;
    EXPECT_GT(t->subject_px.z, t->subject_px.x) << name;  // kept beside what it names
    EXPECT_TRUE(t->subject_px.x >= 0 && t->subject_px.z <= 640 && t->subject_px.y >= 0 && t->subject_px.w <= 360) << name;
  }
  // A curve's name has the whole curve on screen as its subject: it is pinned beside where the curve goes.
  const ViewportProjection project(v.camera, 640, 360);
  for (const std::string name : {"polhode", "herpolhode"}) {
    const auto t = std::find_if(v.texts.begin(), v.texts.end(), [&](const TextItem& x) { return x.text == name; });
    const auto curve = std::find_if(v.polylines.begin(), v.polylines.end(), [&](const PolylineItem& l) { return l.name == name; });
    ASSERT_NE(curve, v.polylines.end()) << name;
    for (const glm::dvec3& q : curve->points) {
      glm::vec2 px;
      ASSERT_TRUE(project(q, px));
      EXPECT_TRUE(px.x >= t->subject_px.x && px.x <= t->subject_px.z && px.y >= t->subject_px.y && px.y <= t->subject_px.w)
          << name;
    }
  }
}

TEST(MomentumSphere, DotStaysOnTheSphereAndTheEnergyEllipsoid) {
  const Tumbler b;
  const Eigen::Vector3d I = b.model.inertia;
  const double L = b.s0.L.norm(), two_E = 2 * kinetic_energy(b.model, b.s0);
  for (const BodyState& s : b.run(80, 0.05)) {
    MomentumSphereInput in{I, momentum_body(s), {}, two_E};
    View v;
    build_momentum_sphere(v, in);
    const auto dot = std::find_if(v.points.begin(), v.points.end(), [](const PointItem& p) { return p.name == "momentum_point"; });
    ASSERT_NE(dot, v.points.end());
    const glm::dvec3 d = dot->position;  // in units of |L|
    const Eigen::Vector3d pi = momentum_body(s);
    const glm::dvec3 u(pi.x() / L, pi.y() / L, pi.z() / L);
    EXPECT_NEAR(pi.norm() / L, 1.0, 1e-9);
    EXPECT_NEAR(pi.cwiseAbs2().cwiseQuotient(I).sum() / two_E, 1.0, 1e-9);
    const glm::dvec3 lifted = 1.02 * u;  // the dot stands a little off the sphere, along Π
    if (hidden_by_ball(v.camera.position, lifted, kSphereBall)) {
      // Behind the ball it shows through, faintly: drawn where Π's own pixel is (on the eye's ray to Π).
      const glm::dvec3 a = glm::normalize(d - v.camera.position), b = glm::normalize(lifted - v.camera.position);
      EXPECT_NEAR(glm::dot(a, b), 1.0, 1e-9);
      // Points are drawn opaque: faint is a colour near the ball's (a pale grey for the black dot).
      EXPECT_EQ(dot->color.a, 1.0f);
      EXPECT_GT(glm::length(glm::vec3(dot->color)), 1.0f);
    } else {
      // In front it is lifted a little off the sphere, along Π, so no curve on the sphere covers it.
      EXPECT_NEAR(glm::dot(glm::normalize(d), u), 1.0, 1e-12);
      EXPECT_GE(glm::length(d), 1.0);
      EXPECT_LE(glm::length(d), 1.05);
    }
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

// The energy ellipsoid meets the sphere on the polhode, and is
// left out where it would fill the view (near e₁ its e₃ semi-axis is √(I₃/I₁)).
TEST(MomentumSphere, EnergyEllipsoidMeetsTheSphereOnThePolhode) {
  const Eigen::Vector3d I(1, 2, 2.5);
  const double L = 2.0;
  for (double two_E : {L * L / 2.4, L * L / 1.9}) {
    View v;
    const Eigen::Vector3d pi = polhodes(I, L, two_E, 8)[0][0];
    build_momentum_sphere(v, {I, pi, {}, two_E});
    ASSERT_EQ(v.surfaces.size(), 1u) << two_E;
    EXPECT_LT(v.surfaces[0].color.a, 0.5f);
    // Only what shows outside the ball: every corner on the ellipsoid and on or outside the
    // sphere, its edges on the sphere itself, so it meets it on the polhode, exactly.
    const SurfaceMesh& mesh = *v.surfaces[0].mesh;
    ASSERT_GT(mesh.positions.size(), 300u);
    int on_sphere = 0;
    for (const glm::vec3& q : mesh.positions) {
      const Eigen::Vector3d p(q.x, q.y, q.z);  // units of |L|
      EXPECT_NEAR(p.cwiseAbs2().cwiseQuotient(I).sum() * L * L / two_E, 1.0, 1e-5);
      EXPECT_GE(p.norm(), 1.0 - 1e-5);
      on_sphere += std::abs(p.norm() - 1.0) < 1e-5;
    }
    EXPECT_GT(on_sphere, 100) << two_E;
  }
  View near_e1;
  const double two_E = L * L / 1.05;
  build_momentum_sphere(near_e1, {I, polhodes(I, L, two_E, 8)[0][0], {}, two_E});
  EXPECT_TRUE(near_e1.surfaces.empty());  // √(2E I₃)/|L| ≈ 1.54 > kEnergyEllipsoidReach
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
  // The view draws it dashed, in the separatrix's colour (not e1's), its dashes
  // reaching +e2 (units of |L|) from both circles' sides: within a dash of the saddle.
  View v;
  build_momentum_sphere(v, {I, Eigen::Vector3d(0.1, 1.9, 0.2), {}, 2.0});
  double nearest = 1e9;
  int dashes = 0;
  for (const PolylineItem& p : v.polylines)
    if (p.name == "separatrix") {
      ++dashes;
      EXPECT_EQ(p.color, color_of(Meaning::separatrix, p.color.a));
      EXPECT_NE(glm::vec3(p.color), glm::vec3(kAxisColors[0]));
      for (const glm::dvec3& x : p.points) {
        EXPECT_NEAR(glm::length(x), 1.0, 1e-3);  // a dash's ends lie on chords
        nearest = std::min(nearest, glm::length(x - glm::dvec3(0, 1, 0)));
      }
    }
  EXPECT_GT(dashes, 8);
  EXPECT_LT(nearest, 0.05);
}

TEST(Captions, FadeInHoldFadeOut) {
  EXPECT_EQ(fade_alpha(0.9, 1, 3), 0.0f);
  EXPECT_NEAR(fade_alpha(1.2, 1, 3), 0.5f, 1e-6);
  EXPECT_EQ(fade_alpha(2.0, 1, 3), 1.0f);
  EXPECT_NEAR(fade_alpha(2.9, 1, 3), 0.25f, 1e-6);
  EXPECT_EQ(fade_alpha(3.1, 1, 3), 0.0f);
  EXPECT_NEAR(fade_alpha(1.1, 1, 1.8), 0.5f, 1e-6);  // short span: fades take a quarter each
  // Without fades a caption is shown exactly over its span, and not after it.
  EXPECT_EQ(fade_alpha(0.9, 1, 3, 0), 0.0f);
  EXPECT_EQ(fade_alpha(2.0, 1, 3, 0), 1.0f);
  EXPECT_EQ(fade_alpha(3.1, 1, 3, 0), 0.0f);
  const TextItem c = caption_item("hello", 0.5f, 1280, 720);
  EXPECT_EQ(c.color.a, 0.5f);
  EXPECT_GT(c.position_px.y, 600.0f);
}

TEST(Captions, SpeedBadgeSitsInTheCornerAndNamesTheSpeed) {
  EXPECT_FALSE(speed_badge("", true, 1280, 720, false, 1));
  const auto b = speed_badge("×1/8", true, 1280, 720, false, 1);
  ASSERT_TRUE(b);
  EXPECT_EQ(b->text, "×1/8 slow motion");
  EXPECT_LE(b->position_px.y + b->size_px, 720.0f);
  EXPECT_LE(text_box(*b).x1, 1280.0f);
  EXPECT_GT(b->position_px.x, 640.0f);
  // A long caption shown with it wraps narrower, its lines and backdrop left of the badge.
  std::string text = "a long caption";
  for (int i = 0; i < 40; ++i) text += " with words";
  const std::vector<TextItem> lines = caption_items(text, 1.0f, 1280, 720, 1280.0f - b->position_px.x);
  ASSERT_GE(lines.size(), 2u);
  EXPECT_LT(lines.front().backdrop_px.z, b->position_px.x);
  for (const TextItem& t : lines) EXPECT_LT(text_box(t).x1, b->position_px.x);
}

TEST(Keys, ArrowsAndTrailsNeverShareASwatch) {
  DrawOptions d;
  d.angular_momentum = d.omega = true;
  d.trail_seconds = 1;
  const std::vector<KeyEntry> plain = bodies_key(d, {}), arrows = bodies_key(d, {}, true);
  ASSERT_EQ(arrows.size(), 4u);
  EXPECT_TRUE(same_entry(plain[0], KeyEntry{Swatch::line, plain[0].colors, plain[0].text}));  // as before
  EXPECT_EQ(arrows[0].swatch, Swatch::arrow);  // e₁ e₂ e₃
  EXPECT_EQ(arrows[1].swatch, Swatch::trail);  // their trails, faded
  for (const Color& c : arrows[1].colors) EXPECT_LT(c.a, 0.5f);
  EXPECT_EQ(arrows[2].swatch, Swatch::arrow);  // L
  EXPECT_EQ(arrows[3].swatch, Swatch::arrow);  // ω
  View v;
  add_key(v, arrows, {0, 0}, 12.0f);
  EXPECT_EQ(v.texts[0].text, "\u2192");
}

// The trails are drawn as solid lines: their key swatches touch, where the
// axes' three marks keep a gap.
TEST(Keys, TrailSwatchesTouchAsOneSolidLine) {
  DrawOptions d;
  d.trail_seconds = 1;
  const std::vector<KeyEntry> entries = bodies_key(d, {});
  ASSERT_EQ(entries.size(), 2u);
  ASSERT_EQ(entries[1].colors.size(), 3u);
  View v;
  add_key(v, entries, {0, 0}, 12.0f);
  std::vector<const TextItem*> axes, trails;
  for (const TextItem& t : v.texts)
    if (t.name == "key_swatch") (axes.size() < 3 ? axes : trails).push_back(&t);
  ASSERT_EQ(trails.size(), 3u);
  const float glyph = text_width("\u2501", 12.0f);
  for (int i = 0; i < 2; ++i) {
    EXPECT_LE(trails[i + 1]->position_px.x - trails[i]->position_px.x, glyph) << "trail swatches " << i << " and " << i + 1 << " touch";
    EXPECT_GT(axes[i + 1]->position_px.x - axes[i]->position_px.x, glyph) << "the axes' marks keep a gap";
  }
}

}  // namespace
}  // namespace tumble::viz
