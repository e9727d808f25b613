#include <algorithm>
// What a lecturer reads in a view, GL-free: a key
// lists exactly what its view draws, and a body's label sits beside its body,
// clear of the body's box and its arrows.
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "core/dynamics.hpp"
#include "core/mass_properties.hpp"
#include "viz/captions.hpp"
#include "viz/key.hpp"
#include "viz/momentum_sphere.hpp"
#include "viz/sphere_figure.hpp"
#include "viz/poinsot.hpp"
#include "viz/scene_view.hpp"
#include "viz/text_layout.hpp"

namespace tumble::viz {
namespace {

bool same_rgb(const Color& a, const Color& b) { return glm::length(glm::vec3(a) - glm::vec3(b)) < 0.02f; }

template <class Items, class Pick>
bool any_rgb(const Items& items, const Color& c, Pick pick) {
  for (const auto& i : items)
    if (pick(i) && same_rgb(i.color, c)) return true;
  return false;
}

// An entry is drawn when an item of its swatch's kind has its colour: a
// block a surface or box, a dot a named point, a line an arrow or curve.
bool drawn(const View& v, Swatch s, const Color& c) {
  const auto all = [](const auto&) { return true; };
  switch (s) {
    case Swatch::block:
      for (const BoxItem& b : v.boxes)
        if (same_rgb(b.face, c)) return true;
      return any_rgb(v.surfaces, c, all);
    case Swatch::dot: {  // a marker behind a momentum sphere's ball counts too, drawn faint
      const auto named = [](const PointItem& p) { return !p.name.empty(); };
      return any_rgb(v.points, c, named) || any_rgb(v.points, faint_marker(c), named);
    }
    case Swatch::line: return any_rgb(v.arrows, c, all) || any_rgb(v.polylines, c, all);
    case Swatch::trail: return any_rgb(v.polylines, c, all);
    case Swatch::arrow: return any_rgb(v.arrows, c, all);
  }
  return false;
}

bool keyed(const std::vector<KeyEntry>& key, const Color& c) {
  for (const KeyEntry& e : key)
    for (const Color& k : e.colors)
      if (same_rgb(k, c)) return true;
  return false;
}

// The rule: every entry's colours are drawn in the view, and every arrow and
// named item (the things a viewer follows) has its colour in the key.
void expect_key_lists_what_is_drawn(const std::vector<KeyEntry>& key, const View& v, const std::string& what) {
  for (const KeyEntry& e : key)
    for (const Color& c : e.colors) EXPECT_TRUE(drawn(v, e.swatch, c)) << what << ": the key lists \"" << e.text << "\"";
  // An arrow named where it is drawn (at its tip, or a sphere's axis at its ends) needs no entry.
  const auto named = [&](const ArrowItem& a) {
    if (!a.tip.empty()) return true;
    return std::any_of(v.texts.begin(), v.texts.end(), [&](const TextItem& t) {
      return a.name.rfind("axis", 0) == 0 && t.name == "axis_label_e" + a.name.substr(4);
    });
  };
  for (const ArrowItem& a : v.arrows) EXPECT_TRUE(keyed(key, a.color) || named(a)) << what << ": arrow " << a.name;
  // A curve named on the picture (a text "label_<its name>" in its colour) needs no entry either.
  const auto labelled = [&](const PolylineItem& p) {
    return std::any_of(v.texts.begin(), v.texts.end(),
                       [&](const TextItem& t) { return t.name == "label_" + p.name && same_rgb(t.color, p.color); });
  };
  for (const PolylineItem& p : v.polylines) {
    if (!p.name.empty()) { EXPECT_TRUE(keyed(key, p.color) || labelled(p)) << what << ": curve " << p.name; }
  }
  // A marker behind a momentum sphere's ball is drawn faint: a keyed colour taken towards the ball's.
  const auto faint_keyed = [&](const Color& c) {
    for (const KeyEntry& e : key)
      for (const Color& k : e.colors)
        if (same_rgb(faint_marker(k), c)) return true;
    return false;
  };
  for (const PointItem& p : v.points) {
    if (!p.name.empty()) { EXPECT_TRUE(keyed(key, p.color) || faint_keyed(p.color)) << what << ": point " << p.name; }
  }
  for (const SurfaceItem& s : v.surfaces) {
    // The invariable plane is keyed by its grid's colour; its surface is a pale backdrop under it.
    if (!s.name.empty() && s.name != "plane") { EXPECT_TRUE(keyed(key, s.color)) << what << ": surface " << s.name; }
  }
}

// The momentum sphere near each axis (tennis_racket.toml's three spheres):
// near e₁ the energy ellipsoid is too large to draw, so its key leaves it out.
TEST(Keys, MomentumSphereKeyListsExactlyWhatItDraws) {
  const Eigen::Vector3d I(1, 2, 3);
  int with_ellipsoid = 0;
  for (const Eigen::Vector3d& pi : {Eigen::Vector3d(1.9, 0.2, 0.3), Eigen::Vector3d(0.2, 1.9, 0.3),
                                    Eigen::Vector3d(0.2, 0.3, 1.9)}) {
    MomentumSphereInput in;
    in.inertia = I, in.momentum = pi, in.two_E = pi.cwiseAbs2().cwiseQuotient(I).sum();
    in.history = {0.99 * pi, pi};
    View v;
    build_momentum_sphere(v, in);
    expect_key_lists_what_is_drawn(sphere_key(in), v, "sphere near Π = " + std::to_string(pi.x()));
    with_ellipsoid += draws_energy_ellipsoid(in);
  }
  EXPECT_EQ(with_ellipsoid, 2);  // near e₂ and e₃, not near e₁
}

TEST(Keys, PoinsotAndBodiesKeysListExactlyWhatTheyDraw) {
  PoinsotInput in;
  in.q = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()));
  in.inertia = {1, 2, 3}, in.L = {0.2, 1.9, 0.3};
  const Eigen::Vector3d w = (in.q.conjugate() * in.L).cwiseQuotient(in.inertia);  // ω, principal frame
  in.omega_principal_history = {w, 1.01 * w};
  in.omega_world_history = {in.q * w, in.q * (1.01 * w)};
  View p;
  build_poinsot(p, in);
  expect_key_lists_what_is_drawn(poinsot_key(), p, "poinsot");

  const RigidBodyModel m = make_model("b", compute_mass_properties(make_box({0.6, 0.36, 0.15}, {6, 4, 2}, 1.0), "b"), {});
  InitialConditions ic;
  ic.omega = {0.3, 5.0, 0.3};
  View v;
  DrawOptions d;
  d.angular_momentum = d.omega = true;
  add_bodies(v, {{&m, nullptr, make_state(m, ic), {0.7f, 0.6f, 0.5f, 0.38f}}}, d, nullptr, 0);
  expect_key_lists_what_is_drawn(bodies_key(d, {{"b", {0.7f, 0.6f, 0.5f, 1}}}), v, "bodies");
}

// A body seen from the side with L straight up out of it: its label does not
// sit on the box, nor on the arrow above it (where labels used to go), but
// beside them, and it is kept.
TEST(Labels, BodyLabelSitsBesideItsBodyClearOfItsArrows) {
  View v;
  v.camera.position = {0, -6, 0}, v.camera.target = {0, 0, 0}, v.camera.up = {0, 0, 1};
  const float w = 640, h = 360, size = 16;
  v.boxes.push_back({{0, 0, 0}, glm::dmat3(1.0), {0.6, 0.3, 0.3}, {0.7f, 0.6f, 0.5f, 0.38f}, {0.3f, 0.3f, 0.3f, 1}});
  v.arrows.push_back({{0, 0, 0}, {0, 0, 1.2}, 0.02, kLColor});  // up, through where the label starts
  const auto body = screen_box(v.camera, w, h, box_corners(v.boxes[0]));
  ASSERT_TRUE(body);
  TextItem label{"body", {0.5f * (body->x0 + body->x1) - 20, body->y0 - 1.2f * size}, size, color_of(Meaning::ink)};
  label.name = "label:body";
  label.subject_px = {body->x0, body->y0, body->x1, body->y1};
  v.texts.push_back(label);
  EXPECT_TRUE(settle_labels(v, w, h).empty()) << "none left out";
  ASSERT_EQ(v.texts.size(), 1u) << "the label is left out";
  const Box b = text_box(v.texts[0]);
  EXPECT_FALSE(b.overlaps(*body)) << "on its body";
  glm::vec2 base, tip;
  ASSERT_TRUE(project_to_viewport(v.camera, w, h, {0, 0, 0}, base) && project_to_viewport(v.camera, w, h, {0, 0, 1.2}, tip));
  EXPECT_FALSE(b.overlaps({base.x - 3, tip.y, base.x + 3, base.y})) << "on the L arrow";
  EXPECT_GT(b.y0, body->y1) << "below the body: above it, the arrow is in the way";
}

// A label with no place inside its view (a body filling a view too small for
// its name) is left out and handed back, so the layout can say so.
TEST(Labels, ALabelWithNoPlaceIsLeftOutAndHandedBack) {
  View v;
  v.camera.position = {0, -6, 0}, v.camera.target = {0, 0, 0}, v.camera.up = {0, 0, 1};
  const float w = 60, h = 40, size = 16;
  v.boxes.push_back({{0, 0, 0}, glm::dmat3(1.0), {3, 3, 3}, {0.7f, 0.6f, 0.5f, 0.38f}, {0.3f, 0.3f, 0.3f, 1}});
  TextItem label{"a long body name", {0, 0}, size, color_of(Meaning::ink)};
  label.name = "label:a long body name";
  label.subject_px = {0, 0, w, h};
  v.texts.push_back(label);
  TextItem other{"kept", {0, 0}, size, color_of(Meaning::ink)};
  v.texts.push_back(other);
  const std::vector<TextItem> out = settle_labels(v, w, h);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].text, "a long body name");
  ASSERT_EQ(v.texts.size(), 1u);
  EXPECT_EQ(v.texts[0].text, "kept");
}

// A body drawn see-through (an axis behind it seen) is still solid for the
// arrows' names: a name keeps off it as off an opaque part; a translucent veil does not.
TEST(Labels, ATipNameKeepsOffASeeThroughBodyPart) {
  auto mesh = std::make_shared<SurfaceMesh>();
  for (float x : {-0.35f, 0.35f})
    for (float z : {-0.35f, 0.35f}) mesh->positions.push_back({x, 0.0f, z}), mesh->normals.push_back({0, -1, 0});
  for (const bool see_through : {true, false}) {
    View v;
    v.camera.position = {0, -6, 0}, v.camera.target = {0, 0, 0}, v.camera.up = {0, 0, 1};
    const float w = 640, h = 360, size = 16;
    SurfaceItem part{mesh, glm::dmat4(1.0), {0.7f, 0.6f, 0.5f, 0.6f}};
    part.see_through = see_through;
    v.surfaces.push_back(part);
    v.arrows.push_back({{0, 0, 0}, {0.15, 0, 0.15}, 0.01, kAxisColors[2], "e3", "e\u2083"});  // its tip inside the part
    EXPECT_TRUE(label_arrow_tips(v, w, h, size, true).empty());
    ASSERT_EQ(v.texts.size(), 1u);
    glm::vec2 a, b;
    ASSERT_TRUE(project_to_viewport(v.camera, w, h, {-0.35, 0, -0.35}, a) && project_to_viewport(v.camera, w, h, {0.35, 0, 0.35}, b));
    const Box body{std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
    EXPECT_EQ(text_box(v.texts[0]).overlaps(body), !see_through) << (see_through ? "see-through part" : "veil");
  }
}

}  // namespace
}  // namespace tumble::viz
