// Shipped scenes load; keys reach the Scene with the documented meaning and defaults.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "core/dynamics.hpp"
#include "core/mass_properties.hpp"
#include "core/particle_cloud.hpp"
#include "scene/reader.hpp"
#include "scene/scene.hpp"

namespace fs = std::filesystem;
using namespace tumble;
using scene::load_scene;
using scene::load_scene_from_string;

namespace {

const fs::path kScenes = fs::path(TUMBLE_SOURCE_DIR) / "scenes";
constexpr const char* kRefParticles =
    "particles = [[1, 0, 0, 1], [-1, 0, 0, 1], [0, 1, 0, 0.5], [0, -1, 0, 0.5]]\n";

TEST(ShippedScenes, EveryOneLoads) {
  int count = 0;
  for (const auto& e : fs::directory_iterator(kScenes)) {
    if (e.path().extension() != ".toml") continue;
    SCOPED_TRACE(e.path().string());
    const scene::Scene s = load_scene(e.path());
    ++count;
    EXPECT_FALSE(s.bodies.empty());
    EXPECT_EQ(s.content_hash.size(), 16u);
    EXPECT_TRUE(s.warnings.empty());
    for (const auto& b : s.bodies) {
      EXPECT_GT(b.model.mass, 0);
      EXPECT_TRUE(b.initial.all_finite());
    }
  }
  EXPECT_GE(count, 6);
}

TEST(ShippedScenes, RequiredDemosExist) {
  for (const char* n : {"dzhanibekov", "stable_spin", "symmetric_top", "thrown_box", "methods_compare", "reference"})
    EXPECT_TRUE(fs::exists(kScenes / (std::string(n) + ".toml"))) << n;
  const auto cmp = load_scene(kScenes / "methods_compare.toml");
  EXPECT_EQ(cmp.render.compare_methods,
            (std::vector<Method>{Method::euler, Method::rk4, Method::exact}));
  EXPECT_EQ(load_scene(kScenes / "stable_spin.toml").bodies.size(), 3u);
}

TEST(ShippedScenes, ReferenceProblem) {
  const auto s = load_scene(kScenes / "reference.toml");
  ASSERT_EQ(s.bodies.size(), 1u);
  const auto& b = s.bodies[0];
  EXPECT_DOUBLE_EQ(b.model.mass, 3.0);
  EXPECT_NEAR(b.model.inertia.x(), 1.0, 1e-14);
  EXPECT_NEAR(b.model.inertia.y(), 2.0, 1e-14);
  EXPECT_NEAR(b.model.inertia.z(), 3.0, 1e-14);
  EXPECT_TRUE(omega_body(b.model, b.initial).isApprox(Eigen::Vector3d(0.01, 10, 0.01), 1e-14));
  EXPECT_DOUBLE_EQ(s.simulation.duration, 10.0);
  EXPECT_TRUE(b.model.forces.empty());
}

// The rackets are drawn in parts (face, green +e₂ edge, dark grip) of one
// 15 × 6 × 2 lattice: the mass, centre and inertia are the plain box's, so
// the colours change nothing the flips depend on.
TEST(ShippedScenes, TennisRacketsInColouredPartsAreThePlainLatticeBox) {
  const auto s = load_scene(kScenes / "tennis_racket.toml");
  const MassProperties box = compute_mass_properties(make_box({0.3, 0.12, 0.02}, {15, 6, 2}, 1.0), "box");
  ASSERT_EQ(s.bodies.size(), 3u);
  for (const auto& b : s.bodies) {
    EXPECT_NEAR(b.model.mass, 1.0, 1e-12) << b.name;
    EXPECT_LT((b.model.inertia - box.principal_moments).norm(), 1e-12 * box.principal_moments.norm()) << b.name;
    EXPECT_LT((b.model.com_cloud - Eigen::Vector3d(box.com)).norm(), 1e-12) << b.name;
  }
}

TEST(SceneKeys, DefaultsAndOverrides) {
  const auto s = load_scene_from_string(std::string("[[bodies]]\n") + kRefParticles, "t.toml");
  EXPECT_EQ(s.name, "scene");
  EXPECT_EQ(s.bodies[0].name, "body0");
  EXPECT_FALSE(s.simulation.automatic);
  EXPECT_EQ(s.simulation.step.method, Method::splitting);
  EXPECT_DOUBLE_EQ(s.simulation.step.dt, 1e-3);
  EXPECT_EQ(s.render.output.width, 1280);
  EXPECT_EQ(s.render.output.msaa, 4);
  EXPECT_EQ(s.render.output.aa, scene::Antialias::fxaa);
  EXPECT_TRUE(s.render.camera.automatic);
  EXPECT_FALSE(s.render.draw.box.has_value());  // the principal box: for bodies without a surface
  EXPECT_TRUE(s.render.draw.surface);
  EXPECT_FALSE(s.render.draw.particles);
  EXPECT_TRUE(s.render.compare_methods.empty());
}

TEST(SceneKeys, AutoMethodPicksExactOnlyWhenTorqueFree) {
  const auto s = load_scene_from_string(std::string("[simulation]\nmethod = \"auto\"\n[[bodies]]\nname = \"free\"\n") +
                                            kRefParticles + "[[bodies]]\nname = \"damped\"\nangular_damping = 0.1\n" +
                                            kRefParticles,
                                        "t.toml");
  EXPECT_TRUE(s.simulation.automatic);
  EXPECT_EQ(scene::step_config(s.simulation, s.bodies[0].model).method, Method::exact);
  EXPECT_EQ(scene::step_config(s.simulation, s.bodies[1].model).method, Method::splitting);
}

// With a tolerance, auto measures the candidates on each body (core's
// method_choice_test checks the picks against a reference) and says why.
TEST(SceneKeys, AutoWithToleranceMeasuresEachBody) {
  const auto s = load_scene_from_string(std::string("[simulation]\nmethod = \"auto\"\ntolerance = 1e-5\nduration = 2\n"
                                                    "[[bodies]]\nname = \"free\"\n") +
                                            kRefParticles + "omega_body = [0.1, 3, 0.1]\n[[bodies]]\nname = \"pushed\"\n"
                                            "torque_body = [0, 0, 0.5]\nomega_body = [0.1, 3, 0.1]\n" + kRefParticles,
                                        "t.toml");
  ASSERT_TRUE(s.simulation.tolerance.has_value());
  EXPECT_EQ(*s.simulation.tolerance, 1e-5);
  const scene::MethodPlan free = scene::plan_method(s.simulation, s.bodies[0]);
  EXPECT_EQ(free.config.method, Method::exact);
  EXPECT_TRUE(free.candidates.empty());
  const scene::MethodPlan pushed = scene::plan_method(s.simulation, s.bodies[1]);
  EXPECT_FALSE(pushed.candidates.empty());
  EXPECT_NE(pushed.reason.find(std::string(method_name(pushed.config.method))), std::string::npos) << pushed.reason;
  EXPECT_NE(pushed.reason.find("tolerance 1e-05"), std::string::npos) << pushed.reason;
  // A method named by the scene is used as written, with no reason given.
  scene::SimulationConfig fixed = s.simulation;
  fixed.automatic = false;
  fixed.step.method = Method::rk4;
  EXPECT_EQ(scene::plan_method(fixed, s.bodies[1]).config.method, Method::rk4);
  EXPECT_TRUE(scene::plan_method(fixed, s.bodies[1]).reason.empty());
}

TEST(SceneKeys, ForcesReachTheModel) {
  const auto s = load_scene_from_string(std::string("[forces]\ngravity = [0, 0, -9.81]\n[[bodies]]\n") + kRefParticles +
                                            "torque_body = [0, 0, 1]\nlinear_damping = 0.5\n"
                                            "[[bodies.forces]]\nforce = [1, 0, 0]\npoint = [0, 1, 0]\nframe = \"body\"\n",
                                        "t.toml");
  const ForceSet& f = s.bodies[0].model.forces;
  // Gravity, the point forces, then the body keys in force_kinds() order.
  ASSERT_EQ(f.terms.size(), 4u);
  ASSERT_NE(f.find<UniformGravity>(), nullptr);
  EXPECT_EQ(f.find<UniformGravity>()->g, Eigen::Vector3d(0, 0, -9.81));
  ASSERT_NE(f.find<ConstantTorque>(), nullptr);
  EXPECT_EQ(f.find<ConstantTorque>()->torque, Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(f.find<ConstantTorque>()->frame, Frame::body);
  ASSERT_NE(f.find<LinearDamping>(), nullptr);
  EXPECT_DOUBLE_EQ(f.find<LinearDamping>()->k, 0.5);
  ASSERT_NE(f.find<PointForce>(), nullptr);
  EXPECT_EQ(f.find<PointForce>()->frame, Frame::body);
  EXPECT_EQ(f.find<PointForce>()->point, Eigen::Vector3d(0, 1, 0));
  EXPECT_TRUE(std::holds_alternative<UniformGravity>(f.terms[0]));
  EXPECT_TRUE(std::holds_alternative<PointForce>(f.terms[1]));
  EXPECT_FALSE(f.conserves_energy());
}

TEST(SceneKeys, InitialConditions) {
  const auto s = load_scene_from_string(std::string("[[bodies]]\n") + kRefParticles +
                                            "position = [1, 2, 3]\nvelocity = [0, 0, 4]\n"
                                            "orientation = [0, 0, 0, 2]\nomega_world = [0, 0, 5]\n",
                                        "t.toml");
  const auto& b = s.bodies[0];
  EXPECT_EQ(b.initial.c, Eigen::Vector3d(1, 2, 3));
  EXPECT_TRUE(velocity(b.model, b.initial).isApprox(Eigen::Vector3d(0, 0, 4)));
  EXPECT_TRUE(omega_world(b.model, b.initial).isApprox(Eigen::Vector3d(0, 0, 5), 1e-14));
  EXPECT_NEAR(std::abs(cloud_orientation(b.model, b.initial).z()), 1.0, 1e-14);  // normalised
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("t.toml:5:15: warning: bodies[0].orientation"), std::string::npos) << s.warnings[0];
}

TEST(SceneKeys, PartsAndCloudFilesAreUnioned) {
  const fs::path dir = fs::temp_directory_path() / ("tumble_scene_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  fs::create_directories(dir);
  std::ofstream(dir / "pair.txt") << "# two particles\n1 0 0 1\n-1 0 0 1\n";
  const auto s = load_scene_from_string(
      "[[bodies]]\ncloud = \"pair.txt\"\n"
      "[[bodies.parts]]\nparticles = [[0, 0, 0, 0.5]]\noffset = [0, 1, 0]\n"
      "[[bodies.parts]]\nparticles = [[0, 0, 0, 0.5]]\noffset = [0, -1, 0]\n",
      "t.toml", dir);
  EXPECT_EQ(s.bodies[0].cloud.size(), 4u);
  EXPECT_NEAR(s.bodies[0].model.inertia.x(), 1.0, 1e-14);
  EXPECT_NEAR(s.bodies[0].model.inertia.z(), 3.0, 1e-14);
  fs::remove_all(dir);
}

TEST(SceneKeys, ShapesGenerateTheirClouds) {
  const auto s = load_scene_from_string(
      "[[bodies]]\nshape = { type = \"box\", size = [1, 2, 3], resolution = [2, 3, 4], mass = 2 }\n"
      "[[bodies]]\nshape = { type = \"ellipsoid\", semi_axes = [1, 2, 3] }\n"
      "[[bodies]]\nshape = { type = \"cylinder\", radius = 0.5, length = 2 }\n"
      "[[bodies]]\nshape = { type = \"t_handle\", handle_length = 0.8, stem_length = 0.4, thickness = 0.1, resolution = 20 }\n",
      "t.toml");
  ASSERT_EQ(s.bodies.size(), 4u);
  EXPECT_EQ(s.bodies[0].cloud.size(), 24u);
  EXPECT_NEAR(s.bodies[0].model.mass, 2.0, 1e-12);
  for (const auto& b : s.bodies) EXPECT_NEAR(b.model.mass, b.name == "body0" ? 2.0 : 1.0, 1e-12);
}

TEST(SceneKeys, RenderSections) {
  const auto s = load_scene_from_string(std::string("[[bodies]]\nname = \"a\"\n") + kRefParticles +
                                            "[output]\nwidth = 640\nheight = 360\nfps = 24\nmsaa = 0\nvideo = \"gif\"\n"
                                            "[camera]\nposition = [1, 2, 3]\nfollow = \"a\"\nfov_y = 50\n"
                                            "[draw]\nparticles = true\ntrails = 2.5\nL = true\n",
                                        "t.toml");
  const auto& r = s.render;
  EXPECT_EQ(r.output.width, 640);
  EXPECT_DOUBLE_EQ(r.output.fps, 24);
  EXPECT_EQ(r.output.msaa, 0);
  EXPECT_EQ(r.output.aa, scene::Antialias::none);  // msaa = 0 without aa: none, as before aa existed
  EXPECT_EQ(r.output.video, scene::VideoFormat::gif);
  EXPECT_FALSE(r.camera.automatic);
  EXPECT_EQ(r.camera.follow, "a");
  EXPECT_DOUBLE_EQ(r.camera.fov_y_deg, 50);
  EXPECT_TRUE(r.draw.particles && r.draw.angular_momentum);
  EXPECT_DOUBLE_EQ(r.draw.trail_seconds, 2.5);
}

TEST(SceneKeys, AntialiasingKeys) {
  auto aa = [](const std::string& output) {
    const auto s = load_scene_from_string(std::string("[[bodies]]\nname = \"a\"\n") + kRefParticles + "[output]\n" + output,
                                          "t.toml");
    return std::pair{s.render.output.aa, s.render.output.msaa};
  };
  EXPECT_EQ(aa(""), std::pair(scene::Antialias::fxaa, 4));
  EXPECT_EQ(aa("msaa = 2\n"), std::pair(scene::Antialias::msaa, 2));  // a scene from before `aa`
  EXPECT_EQ(aa("aa = \"fxaa\"\nmsaa = 2\n"), std::pair(scene::Antialias::fxaa, 2));
  EXPECT_EQ(aa("aa = \"msaa\"\n"), std::pair(scene::Antialias::msaa, 4));
  EXPECT_EQ(aa("aa = \"none\"\n"), std::pair(scene::Antialias::none, 4));
  EXPECT_EQ(scene::antialias_name(scene::Antialias::fxaa), "fxaa");
  EXPECT_EQ(scene::antialias_name(scene::Antialias::none), "none");
}

TEST(SampleTimes, FramesAtKOverFpsEndingAtDuration) {
  auto t = scene::sample_times(1.0, 30);
  EXPECT_EQ(t.size(), 31u);
  EXPECT_EQ(t.front(), 0.0);
  EXPECT_EQ(t.back(), 1.0);
  t = scene::sample_times(0.1, 30);  // 0.1·30 is 3.0000000000000004
  EXPECT_EQ(t.size(), 4u);
  EXPECT_EQ(t.back(), 0.1);
  t = scene::sample_times(1.05, 10);  // not a multiple: the end is appended
  EXPECT_EQ(t.size(), 12u);
  EXPECT_EQ(t.back(), 1.05);
  t = scene::sample_times(1e-12, 30);
  EXPECT_EQ(t, (std::vector<double>{0.0, 1e-12}));
}

TEST(Helpers, Fnv1aAndDidYouMean) {
  EXPECT_EQ(scene::fnv1a_hex(""), "cbf29ce484222325");
  EXPECT_EQ(scene::fnv1a_hex("a"), "af63dc4c8601ec8c");
  EXPECT_EQ(scene::detail::edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(scene::detail::closest("omgea_body", {"omega_body", "omega_world", "name"}), "omega_body");
  EXPECT_EQ(scene::detail::closest("zzzz", {"dt", "fps"}), "");
}

}  // namespace
