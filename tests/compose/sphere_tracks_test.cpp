// A momentum sphere beside a comparison draws every run's Π from t = 0 on the
// one sphere, checked against what a free body must do: the exact path keeps
// its energy level (Σ Π_i²/I_i over |Π|² fixed), explicit Euler's climbs (its
// normalised step adds ½dt²(Π×ω)·I⁻¹(Π×ω) > 0 each time), RK4's ends on the
// exact path.
#include <algorithm>
#include <set>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "compose/frame_builder.hpp"
#include "compose/views/kinds.hpp"
#include "compose/world_views.hpp"
#include "scene/frame_clock.hpp"
#include "scene/frame_runs.hpp"
#include "scene/scene.hpp"

namespace tumble {
namespace {

// 2E/|L|² of a point on the drawn sphere (any radius): the energy level it lies on.
double level(const glm::dvec3& x, const Eigen::Vector3d& inertia) {
  return (x.x * x.x / inertia[0] + x.y * x.y / inertia[1] + x.z * x.z / inertia[2]) / glm::dot(x, x);
}

const viz::PolylineItem* coloured(const viz::View& v, const viz::Color& c) {
  const auto it = std::find_if(v.polylines.begin(), v.polylines.end(), [&](const viz::PolylineItem& p) { return p.color == c; });
  return it == v.polylines.end() ? nullptr : &*it;
}

// A scene's last frame as drawn at 960x540, with the runs it was drawn from.
struct LastFrame {
  scene::Scene scene;
  std::vector<scene::Run> runs;
  viz::DrawList dl;
};

LastFrame last_frame(const std::filesystem::path& file) {
  LastFrame f{scene::load_scene(file), {}, {}};
  const double fps = f.scene.render.output.fps;
  const long count = scene::frame_clock(f.scene, fps).count();
  f.runs = scene::simulate_runs(f.scene, count, fps);
  f.dl = compose::FrameBuilder(f.scene, f.runs, fps, 960, 540).build(count - 1);
  return f;
}

// The frame's momentum sphere; end() when it has none.
std::vector<viz::View>::const_iterator sphere_of(const viz::DrawList& dl) {
  return std::find_if(dl.views.begin(), dl.views.end(), [](const viz::View& v) { return v.name == "momentum_sphere"; });
}

TEST(SphereTracks, AComparisonsSphereDrawsEachMethodsPathAgainstTheExactOne) {
  const LastFrame f = last_frame(std::filesystem::path(TUMBLE_SOURCE_DIR) / "scenes" / "methods_compare.toml");  // t = 16 s
  const scene::Scene& s = f.scene;
  const auto& runs = f.runs;
  ASSERT_EQ(runs.size(), 3u);
  const auto sphere = sphere_of(f.dl);
  ASSERT_NE(sphere, f.dl.views.end());
  // The paths by their colours (the methods' unnamed: the axes' names may sit over them at the crowded saddles).
  const viz::PolylineItem* exact = coloured(*sphere, compose::kExactPathColor);
  const viz::PolylineItem* euler = coloured(*sphere, compose::run_color(runs[0]));
  const viz::PolylineItem* rk4 = coloured(*sphere, compose::run_color(runs[1]));
  ASSERT_TRUE(exact && euler && rk4);
  EXPECT_LT(exact, euler) << "the exact path first, under the methods'";
  EXPECT_LT(exact, rk4);
  EXPECT_GT(exact->width_px, rk4->width_px) << "wide enough to show round the path that lies on it";
  const Eigen::Vector3d& inertia = s.bodies[0].model.inertia;
  // The exact path keeps to one level; it runs from t = 0 (Π at +e₂) round e₃ and back through flips.
  const double e0 = level(exact->points.front(), inertia);
  for (const glm::dvec3& x : exact->points) ASSERT_NEAR(level(x, inertia) / e0, 1.0, 1e-6);
  EXPECT_GT(exact->points.front().y / glm::length(exact->points.front()), 0.999) << "Π starts at +e₂";
  // Each path ends in its dot, Π now: Euler's E up by more than a third by 16 s (+45 %, the cell's
  // readout; its path starts on the exact level); RK4's where the exact one is (unit sphere, a hair out).
  EXPECT_NEAR(level(euler->points.front(), inertia) / e0, 1.0, 1e-6);
  auto dot = [&](const viz::Color& c) {
    const auto it = std::find_if(sphere->points.begin(), sphere->points.end(), [&](const viz::PointItem& p) { return p.color == c; });
    EXPECT_NE(it, sphere->points.end());
    return it == sphere->points.end() ? glm::dvec3(0, 1, 0) : it->position;
  };
  EXPECT_GT(level(dot(compose::run_color(runs[0])), inertia) / e0, 1.35);
  EXPECT_LT(glm::length(dot(compose::run_color(runs[1])) - dot(compose::kExactPathColor)), 1e-2);

}

// A sphere's `paths_of` (a poinsot ending kept as a test scene): each body's Π on the one sphere, scaled
// by |L| of the view's body over its own: on the unit sphere, each on its own
// level 2E/|L|² (the same box spun twice: box 1's loop well inside e₃'s
// region, box 2's just below the separatrix's 1/I₂), from t = 0 to now.
TEST(SphereTracks, PathsOfSeveralBodiesLieOnTheOneSphereEachOnItsOwnLevel) {
  const LastFrame f = last_frame(std::filesystem::path(TUMBLE_SOURCE_DIR) / "tests" / "compose" / "scenes" / "poinsot_paths_of.toml");
  const scene::Scene& s = f.scene;
  const auto& runs = f.runs;
  const auto sphere = sphere_of(f.dl);
  ASSERT_NE(sphere, f.dl.views.end());
  const Eigen::Vector3d& inertia = s.bodies[0].model.inertia;
  double levels[2] = {0, 0};
  for (std::size_t b = 0; b < 2; ++b) {
    const auto path = std::find_if(sphere->polylines.begin(), sphere->polylines.end(),
                                   [&](const viz::PolylineItem& p) { return p.name == "polhode " + s.bodies[b].label; });
    ASSERT_NE(path, sphere->polylines.end()) << s.bodies[b].label;
    const Eigen::Vector3d pi0 = runs[0].frames[0][b].q.conjugate() * runs[0].frames[0][b].L;
    const double own = pi0.cwiseProduct(inertia.cwiseInverse()).dot(pi0) / pi0.squaredNorm();
    for (const glm::dvec3& x : path->points) {
      ASSERT_NEAR(glm::length(x), 1.004, 1e-6) << s.bodies[b].label << ": on the one sphere, a hair out";
      ASSERT_NEAR(level(x, inertia) / own, 1.0, 1e-6) << s.bodies[b].label;
    }
    EXPECT_GT(path->points.size(), 100u) << "from t = 0";
    levels[b] = own;
  }
  // Both round e₃ (below the separatrix's 1/I₂), box 1 well inside, box 2 just below it: two curves, not one.
  EXPECT_LT(levels[0], levels[1] - 0.1 * (levels[1] - 1 / inertia[2]));
  EXPECT_LT(levels[1], 1 / inertia[1]);
  EXPECT_GT(levels[1], 1 / inertia[1] - 0.02 * (1 / inertia[1] - 1 / inertia[2]));
}

// paths_of without path_on_top: the bodies' paths under the separatrix's dashes (drawn first), so a
// path a fraction of a degree beside it (tennis_racket's middle racket) leaves it seen; the dots over all.
TEST(SphereTracks, PathsOfLieUnderTheSeparatrixAndTheirDotsOverIt) {
  const LastFrame f = last_frame(std::filesystem::path(TUMBLE_SOURCE_DIR) / "scenes" / "tennis_racket.toml");
  const auto sphere = sphere_of(f.dl);
  ASSERT_NE(sphere, f.dl.views.end());
  std::size_t last_path = 0, first_dash = sphere->polylines.size();
  std::set<std::string> paths;  // a path split where it passes behind the ball keeps its name
  for (std::size_t i = 0; i < sphere->polylines.size(); ++i) {
    const std::string& n = sphere->polylines[i].name;
    if (n.rfind("polhode ", 0) == 0) last_path = i, paths.insert(n);
    if (n == "separatrix") first_dash = std::min(first_dash, i);
  }
  EXPECT_EQ(paths.size(), 3u);  // the three rackets' Π
  EXPECT_LT(last_path, first_dash);
}

// paths_of of bodies in one colour (poinsot's two sand boxes): every path in the polhode's
// crimson, one key entry; of bodies in different colours (tennis_racket's rackets): each path
// in its body's colour, one key entry per body, so each dot is matched to its racket.
TEST(SphereTracks, PathsOfTakeTheirBodiesColoursWhenTheBodiesDiffer) {
  const LastFrame same = last_frame(std::filesystem::path(TUMBLE_SOURCE_DIR) / "tests" / "compose" / "scenes" / "poinsot_paths_of.toml");
  const LastFrame differ = last_frame(std::filesystem::path(TUMBLE_SOURCE_DIR) / "scenes" / "tennis_racket.toml");
  auto path_colours = [](const LastFrame& f) {
    std::set<std::string> names;
    std::vector<viz::Color> colours;
    for (const viz::PolylineItem& p : sphere_of(f.dl)->polylines)
      if (p.name.rfind("polhode ", 0) == 0 && names.insert(p.name).second) colours.push_back(p.color);
    return colours;
  };
  for (const viz::Color& c : path_colours(same)) EXPECT_EQ(c, viz::color_of(viz::Meaning::polhode));
  const std::vector<viz::Color> c = path_colours(differ);
  ASSERT_EQ(c.size(), 3u);
  EXPECT_FALSE(c[0] == c[1] || c[1] == c[2] || c[0] == c[2]) << "three rackets, three colours";
  const scene::Scene& s = differ.scene;
  for (std::size_t b = 0; b < 3; ++b) {
    const Eigen::Vector3f want = 0.75f * s.bodies[b].color.cast<float>();  // as the key draws a body
    EXPECT_NEAR(c[b].r, want.x(), 1e-6) << s.bodies[b].label;
    EXPECT_NEAR(c[b].g, want.y(), 1e-6) << s.bodies[b].label;
  }
}

}  // namespace
}  // namespace tumble
