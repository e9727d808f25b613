// shape = { type = "mesh" }: real files from Debian's assimp-testmodels, units,
// fills, the mesh report, and every malformed file refused naming the file.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "scene/scene.hpp"

namespace fs = std::filesystem;
using namespace tumble;
using scene::load_scene_from_string;

namespace {

const fs::path kModels = "/usr/share/assimp/models";

scene::Scene load_mesh(const std::string& shape, const fs::path& base = kModels, const std::string& extra = "") {
  return load_scene_from_string("[[bodies]]\nshape = " + shape + "\n" + extra, "mesh.toml", base);
}

std::string error_of(const std::string& shape, const fs::path& base = kModels) {
  try {
    load_mesh(shape, base);
  } catch (const scene::SceneError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected a SceneError for " << shape;
  return "";
}

double rel(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) { return (a - b).norm() / b.norm(); }

TEST(MeshShape, ObjBoxReportAndExactInertia) {
  const scene::Scene s = load_mesh(R"({ type = "mesh", file = "OBJ/box.obj", mass = 6.0, resolution = 20 })");
  ASSERT_EQ(s.bodies.size(), 1u);
  const scene::Body& b = s.bodies[0];
  ASSERT_EQ(b.meshes.size(), 1u);
  const scene::MeshSource& m = b.meshes[0];
  EXPECT_EQ(m.report.triangles, 12u);
  EXPECT_EQ(m.report.vertices, 8u);
  EXPECT_TRUE(m.report.watertight());
  EXPECT_NEAR(m.report.signed_volume, 1.0, 1e-12);
  EXPECT_EQ(m.report.box_min, Eigen::Vector3d::Constant(-0.5));
  EXPECT_FALSE(m.flipped);
  ASSERT_TRUE(m.has_exact);
  // Unit cube of 6 kg: J = M/6 I.
  EXPECT_LT(rel(m.exact_inertia, Eigen::Matrix3d::Identity()), 1e-12);
  EXPECT_NEAR(b.mass_properties.mass, 6.0, 1e-9);
  EXPECT_EQ(m.particles, b.cloud.size());
  EXPECT_LT(m.inertia_error(), 0.05);
  EXPECT_TRUE(s.warnings.empty());
}

TEST(MeshShape, BinaryPlyCubeAndDensity) {
  const scene::Scene s = load_mesh(R"({ type = "mesh", file = "PLY/cube_binary.ply", density = 1000.0 })");
  const scene::MeshSource& m = s.bodies[0].meshes[0];
  EXPECT_TRUE(m.report.watertight());
  EXPECT_GT(m.report.triangles, 0u);
  EXPECT_NEAR(s.bodies[0].mass_properties.mass, 1000.0 * std::abs(m.report.signed_volume), 1e-6);
}

// The same object in mm and in m: mass and particle count agree, lengths scale
// by 1e-3 and the inertia by 1e-6.
TEST(MeshShape, UnitsScaleTheObject) {
  const scene::Scene m = load_mesh(R"({ type = "mesh", file = "OBJ/box.obj", units = "m", mass = 2.0 })");
  const scene::Scene mm = load_mesh(R"({ type = "mesh", file = "OBJ/box.obj", units = "mm", mass = 2.0 })");
  const scene::Scene in = load_mesh(R"({ type = "mesh", file = "OBJ/box.obj", units = "in", mass = 2.0 })");
  const scene::MeshSource &a = m.bodies[0].meshes[0], &b = mm.bodies[0].meshes[0];
  EXPECT_EQ(a.particles, b.particles);
  EXPECT_NEAR(b.report.signed_volume, 1e-9, 1e-21);
  EXPECT_LT(rel(b.exact_inertia, 1e-6 * a.exact_inertia), 1e-12);
  EXPECT_LT(rel(mm.bodies[0].mass_properties.inertia, 1e-6 * m.bodies[0].mass_properties.inertia), 1e-9);
  EXPECT_NEAR(in.bodies[0].meshes[0].report.box_max.x(), 0.5 * 0.0254, 1e-15);
}

TEST(MeshShape, NotWatertightSaysWhetherTheInsideTestToleratesIt) {
  // A small hole: the winding number tolerates it, with a warning that says so.
  const scene::Scene s = load_mesh(R"({ type = "mesh", file = "STL/sphereWithHole.stl" })");
  const scene::MeshSource& m = s.bodies[0].meshes[0];
  EXPECT_FALSE(m.report.watertight());
  EXPECT_GT(m.report.boundary_edges, 0u);
  EXPECT_FALSE(m.has_exact);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("not watertight"), std::string::npos) << s.warnings[0];
  EXPECT_NE(s.warnings[0].find("tolerates"), std::string::npos) << s.warnings[0];
  // An exact tolerance needs an exact tensor.
  const std::string e =
      error_of(R"({ type = "mesh", file = "STL/sphereWithHole.stl", inertia_tolerance = 1e-3 })");
  EXPECT_NE(e.find("not watertight"), std::string::npos) << e;
  EXPECT_NE(e.find("sphereWithHole.stl"), std::string::npos) << e;
}

TEST(MeshShape, LargeHolesAreAnError) {
  const fs::path dir = fs::temp_directory_path() / ("tumble_mesh_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // A unit cube missing its top face: half the lattice has w near 0.5.
  std::ofstream(dir / "open.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                                     "f 1 4 3 2\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
  const std::string e = error_of(R"({ type = "mesh", file = "open.obj" })", dir);
  EXPECT_NE(e.find("open.obj"), std::string::npos) << e;
  EXPECT_NE(e.find("too large for it to tolerate"), std::string::npos) << e;
  // The same cube inside out is flipped, with a warning, to the same body.
  std::ofstream(dir / "inverted.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                                         "f 2 3 4 1\nf 5 6 2 1\nf 6 7 3 2\nf 7 8 4 3\nf 8 5 1 4\nf 8 7 6 5\n";
  const scene::Scene s = load_mesh(R"({ type = "mesh", file = "inverted.obj", resolution = 10 })", dir);
  const scene::MeshSource& m = s.bodies[0].meshes[0];
  EXPECT_TRUE(m.flipped);
  EXPECT_LT(m.report.signed_volume, 0);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("inside out"), std::string::npos) << s.warnings[0];
  EXPECT_LT(rel(m.exact_inertia, Eigen::Matrix3d::Identity() / 6), 1e-12);
  // Volume 1 at spacing 0.1 on a turned lattice: 1000 points, give or take the surface's.
  EXPECT_NEAR(double(m.particles), 1000.0, 30.0);
  fs::remove_all(dir);
}

TEST(MeshShape, EveryMalformedOrEmptyFileIsRefusedNamingIt) {
  int count = 0;
  for (const auto& e : fs::directory_iterator(kModels / "invalid")) {
    // malformed2.obj (an empty face line, a missing material) loads as a box
    // without its top: refused as a volume with holes too large.
    if (e.path().extension() == ".txt") continue;
    SCOPED_TRACE(e.path().string());
    const std::string rel_path = "invalid/" + e.path().filename().string();
    const std::string msg = error_of("{ type = \"mesh\", file = \"" + rel_path + "\" }");
    EXPECT_NE(msg.find(e.path().filename().string()), std::string::npos) << msg;
    ++count;
  }
  EXPECT_GE(count, 14);
  EXPECT_NE(error_of(R"({ type = "mesh", file = "nope.stl" })").find("nope.stl"), std::string::npos);
}

TEST(MeshShape, KeysAreChecked) {
  EXPECT_NE(error_of(R"({ type = "mesh", file = "OBJ/box.obj", units = "ft" })").find("\"mm\""), std::string::npos);
  EXPECT_NE(error_of(R"({ type = "mesh", file = "OBJ/box.obj", fill = "solid" })").find("\"volume\""),
            std::string::npos);
  EXPECT_NE(error_of(R"({ type = "mesh", file = "OBJ/box.obj", mass = 1, density = 2 })").find("not both"),
            std::string::npos);
  EXPECT_NE(error_of(R"({ type = "mesh" })").find("missing"), std::string::npos);
}

// inertia_tolerance picks the coarsest lattice of its ladder within the tolerance.
TEST(MeshShape, InertiaTolerancePicksALatticeWithinIt) {
  for (double tol : {1e-2, 1e-3}) {
    const scene::Scene s =
        load_mesh(R"({ type = "mesh", file = "PLY/cube_binary.ply", inertia_tolerance = )" + std::to_string(tol) + " }");
    const scene::MeshSource& m = s.bodies[0].meshes[0];
    EXPECT_LE(m.inertia_error(), tol);
    EXPECT_GT(m.particles, 0u);
  }
}

// The ladder (resolution 8, ×1.2 per rung, rounded up) stops at the first rung
// within the tolerance: the same cloud, bit for bit, as that resolution given
// directly, while the rung before misses the tolerance.
TEST(MeshShape, InertiaToleranceStopsAtTheFirstRungWithinIt) {
  const double tol = 1e-3;
  const scene::Scene s = load_mesh(R"({ type = "mesh", file = "OBJ/box.obj", inertia_tolerance = 1e-3 })");
  const scene::MeshSource& m = s.bodies[0].meshes[0];
  const long long chosen = std::llround((m.report.box_max - m.report.box_min).maxCoeff() / m.spacing);
  std::vector<long long> rungs{8};
  while (rungs.back() < chosen) rungs.push_back(static_cast<long long>(std::ceil(double(rungs.back()) * 1.2)));
  ASSERT_EQ(rungs.back(), chosen);
  ASSERT_GE(rungs.size(), 2u);
  auto at = [](long long r) {
    return load_mesh(R"({ type = "mesh", file = "OBJ/box.obj", resolution = )" + std::to_string(r) + " }");
  };
  const scene::Scene direct = at(chosen);
  ASSERT_EQ(direct.bodies[0].cloud.size(), s.bodies[0].cloud.size());
  for (std::size_t i = 0; i < s.bodies[0].cloud.size(); ++i)
    ASSERT_EQ(direct.bodies[0].cloud[i].position, s.bodies[0].cloud[i].position) << i;
  EXPECT_EQ(direct.bodies[0].meshes[0].cloud_inertia, m.cloud_inertia);
  EXPECT_LE(m.inertia_error(), tol);
  EXPECT_GT(at(rungs[rungs.size() - 2]).bodies[0].meshes[0].inertia_error(), tol);
}

TEST(MeshShape, SurfaceAndVerticesFills) {
  const scene::Scene s = load_mesh(R"({ type = "mesh", file = "OBJ/box.obj", fill = "surface", mass = 3.0, resolution = 60 })");
  const scene::MeshSource& m = s.bodies[0].meshes[0];
  ASSERT_TRUE(m.has_exact);
  EXPECT_LT(rel(m.exact_inertia, 5.0 / 18 * 3.0 * Eigen::Matrix3d::Identity()), 1e-12);  // hollow cube
  EXPECT_LT(m.inertia_error(), 0.03);
  const scene::Scene v = load_mesh(R"({ type = "mesh", file = "OBJ/box.obj", fill = "vertices", mass = 8.0 })");
  EXPECT_EQ(v.bodies[0].cloud.size(), 8u);
  EXPECT_NEAR(v.bodies[0].mass_properties.inertia(0, 0), 8.0 * 0.5, 1e-12);  // 8 corners at r² = 0.5
}

TEST(Parts, OrientationAndColor) {
  const std::string text = R"([[bodies]]
[[bodies.parts]]
shape = { type = "box", size = [2.0, 0.5, 0.25], resolution = [8, 4, 2] }
orientation = [0.7071067811865476, 0, 0, 0.7071067811865476]
color = [1.0, 0.0, 0.0]
[[bodies.parts]]
shape = { type = "box", size = [2.0, 0.5, 0.25], resolution = [8, 4, 2] }
offset = [0, 0, 3]
)";
  const scene::Scene s = load_scene_from_string(text, "parts.toml");
  const scene::Body& b = s.bodies[0];
  ASSERT_EQ(b.cloud.size(), 128u);
  // The first part is turned 90° about z: its long side lies along y.
  double ymax = 0;
  for (std::size_t i = 0; i < 64; ++i) ymax = std::max(ymax, std::abs(b.cloud[i].position.y()));
  EXPECT_NEAR(ymax, 0.875, 1e-12);
  ASSERT_EQ(b.part_colors.size(), 1u);
  EXPECT_EQ(b.part_colors[0].begin, 0u);
  EXPECT_EQ(b.part_colors[0].end, 64u);
  EXPECT_EQ(b.part_colors[0].color, Eigen::Vector3d(1, 0, 0));
}

}  // namespace
