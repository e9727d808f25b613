// The PLY vertex reader (x, y, z and a per-vertex `mass`) and fill = "vertices"
// with it: ascii and binary files of both byte orders written here with known
// masses, every header error located, truncated and hostile data refused.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "base/error.hpp"
#include "core/mesh_fill.hpp"
#include "scene/ply_vertices.hpp"
#include "scene/scene.hpp"

namespace fs = std::filesystem;
using namespace tumble;
using scene::read_ply_vertices;

namespace {

// Corners (±1, ±2, ±3) m, mass 1 kg each but 9 kg at (1, 2, 3): total 16 kg,
// centre of mass (1, 2, 3) / 2, and about it J = J_corners + 8 (|r|² I − r rᵀ)
// − 16 (|r/2|² I − (r/2)(r/2)ᵀ) = diag(104, 80, 40) + 4 (14 I − r rᵀ).
constexpr double kCorner[3] = {1, 2, 3};
const Eigen::Vector3d kCom(0.5, 1.0, 1.5);
const Eigen::Matrix3d kInertia = (Eigen::Matrix3d() << 156, -8, -12, -8, 120, -24, -12, -24, 60).finished();

double corner(int i, int axis) { return (i >> axis & 1 ? 1 : -1) * kCorner[axis]; }
double corner_mass(int i) { return i == 7 ? 9.0 : 1.0; }

// Packs scalars in the file's byte order.
struct Packer {
  bool big;
  std::string bytes;
  template <class T>
  void put(T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof v);
    if (big) std::reverse(b, b + sizeof v);
    bytes.append(b, sizeof v);
  }
};

// A binary file with an element before the vertices (a list and a scalar per
// record, to be skipped), mixed types and an unused property between.
std::string binary_corners(bool big) {
  std::string h = std::string("ply\nformat binary_") + (big ? "big" : "little") + "_endian 1.0\n" +
                  "comment corners of a 2 x 4 x 6 m box, one heavy\n"
                  "element material 2\nproperty list uint8 int32 ids\nproperty float64 shininess\n"
                  "element vertex 8\nproperty float32 x\nproperty int16 y\nproperty float z\nproperty uchar red\n"
                  "property double mass\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n";
  Packer p{big, h};
  for (int m = 0; m < 2; ++m) {
    p.put<std::uint8_t>(3);
    for (int k = 0; k < 3; ++k) p.put<std::int32_t>(k);
    p.put<double>(0.5);
  }
  for (int i = 0; i < 8; ++i) {
    p.put<float>(float(corner(i, 0)));
    p.put<std::int16_t>(std::int16_t(corner(i, 1)));
    p.put<float>(float(corner(i, 2)));
    p.put<std::uint8_t>(200);
    p.put<double>(corner_mass(i));
  }
  return p.bytes;
}

std::string ascii_corners() {
  std::ostringstream o;
  o << "ply\r\nformat ascii 1.0\r\nobj_info written by ply_vertices_test\r\nelement vertex 8\r\n"
       "property double x\r\nproperty double y\r\nproperty double z\r\nproperty float64 mass\r\n"
       "element face 1\r\nproperty list uint8 uint32 vertex_indices\r\nend_header\r\n";
  for (int i = 0; i < 8; ++i) o << corner(i, 0) << ' ' << corner(i, 1) << ' ' << corner(i, 2) << ' ' << corner_mass(i) << "\r\n";
  o << "3 0 1 2\r\n";
  return o.str();
}

scene::PlyVertices parse(const std::string& text) {
  std::istringstream in(text);
  return read_ply_vertices(in, "t.ply");
}

std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError for:\n" << text;
  return "";
}

class PlyScene : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("tumble_ply_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  scene::Scene load(const std::string& file, const std::string& bytes, const std::string& keys = "") {
    std::ofstream(dir_ / file, std::ios::binary) << bytes;
    return scene::load_scene_from_string(
        "[[bodies]]\nshape = { type = \"mesh\", file = \"" + file + "\", fill = \"vertices\"" + keys + " }\n",
        "ply.toml", dir_);
  }
  fs::path dir_;
};

void expect_corners(const scene::Scene& s, double scale_mass, double scale_length) {
  const scene::Body& b = s.bodies.at(0);
  EXPECT_EQ(b.cloud.size(), 8u);
  EXPECT_NEAR(b.mass_properties.mass, 16 * scale_mass, 1e-12 * scale_mass);
  EXPECT_LT((b.mass_properties.com - scale_length * kCom).norm(), 1e-12 * scale_length);
  const double j = scale_mass * scale_length * scale_length;
  EXPECT_LT((b.mass_properties.inertia - j * kInertia).norm(), 1e-12 * j * kInertia.norm()) << b.mass_properties.inertia;
  const scene::MeshSource& m = b.meshes.at(0);
  EXPECT_EQ(m.file_mass, 16.0);
  EXPECT_LT((m.cloud_inertia - j * kInertia).norm(), 1e-12 * j * kInertia.norm());
}

TEST_F(PlyScene, PerVertexMassesGiveTheClosedFormTensor) {
  expect_corners(load("le.ply", binary_corners(false)), 1, 1);
  expect_corners(load("be.ply", binary_corners(true)), 1, 1);
  expect_corners(load("a.ply", ascii_corners()), 1, 1);
}

TEST_F(PlyScene, ShapeMassRescalesAndUnitsScalePositions) {
  expect_corners(load("le.ply", binary_corners(false), ", mass = 32.0"), 2, 1);
  expect_corners(load("mm.PLY", ascii_corners(), ", units = \"mm\""), 1, 1e-3);
}

TEST_F(PlyScene, ZeroMassVerticesAreLeftOut) {
  std::string text = ascii_corners();
  text.replace(text.find("\n1 -2 -3 1\r"), 11, "\n1 -2 -3 0\r");  // corner 1
  const scene::Scene s = load("z.ply", text);
  EXPECT_EQ(s.bodies[0].cloud.size(), 7u);
  EXPECT_EQ(s.bodies[0].meshes[0].massless_vertices, 1u);
  EXPECT_NEAR(s.bodies[0].mass_properties.mass, 15.0, 1e-12);
}

// Without a mass property a PLY keeps the welded vertices and equal masses.
TEST_F(PlyScene, PlyWithoutMassHasEqualMasses) {
  const fs::path models = "/usr/share/assimp/models/PLY";
  const scene::Scene s = scene::load_scene_from_string(
      "[[bodies]]\nshape = { type = \"mesh\", file = \"cube_binary.ply\", fill = \"vertices\", mass = 8.0 }\n",
      "m.toml", models);
  const scene::Body& b = s.bodies[0];
  ASSERT_EQ(b.cloud.size(), 8u);
  for (const Particle& p : b.cloud) EXPECT_EQ(p.mass, 1.0);
  EXPECT_EQ(b.meshes[0].file_mass, 0.0);
  for (const char* f : {"points.ply", "cube_binary.ply", "Wuson.ply", "cube.ply", "cube_uv.ply"}) {
    SCOPED_TRACE(f);
    const scene::PlyVertices v = read_ply_vertices(models / f);
    EXPECT_TRUE(v.masses.empty());
    EXPECT_GT(v.positions.size(), 3u);
  }
  // A point cloud without faces (assimp refuses those): every point, equal masses.
  const scene::Scene p = scene::load_scene_from_string(
      "[[bodies]]\nshape = { type = \"mesh\", file = \"points.ply\", fill = \"vertices\", mass = 2.0 }\n", "p.toml",
      models);
  ASSERT_EQ(p.bodies[0].cloud.size(), 4u);
  for (const Particle& q : p.bodies[0].cloud) EXPECT_EQ(q.mass, 0.5);
  EXPECT_EQ(p.bodies[0].meshes[0].report.triangles, 0u);
  // issue623.ply declares a list in its vertex element that its data lacks.
  try {
    read_ply_vertices(models / "issue623.ply");
    ADD_FAILURE() << "issue623.ply loaded";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("issue623.ply:14:1: vertex 0: list 'vertex_indices' has length 7.9418"),
              std::string::npos) << e.what();
  }
  // pond.0.ply is damaged (69 bytes short, garbage from about vertex 500; the first NaN is in vertex 714).
  try {
    read_ply_vertices(models / "pond.0.ply");
    ADD_FAILURE() << "pond.0.ply loaded";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("pond.0.ply: vertex 714: position"), std::string::npos) << e.what();
  }
  // Wuson.ply's third line lacks "comment": ignored with a warning, as assimp does.
  const scene::PlyVertices w = read_ply_vertices(models / "Wuson.ply");
  EXPECT_EQ(w.positions.size(), 11184u);
  ASSERT_EQ(w.warnings.size(), 1u);
  EXPECT_NE(w.warnings[0].find("Wuson.ply:3: 'Created'"), std::string::npos) << w.warnings[0];
}

TEST_F(PlyScene, BadMassesAreSceneErrorsNamingTheFile) {
  std::string text = ascii_corners();
  text.replace(text.find("\n1 -2 -3 1\r"), 11, "\n1 -2 -3 -1\r");
  try {
    load("neg.ply", text);
    FAIL();
  } catch (const scene::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("neg.ply: vertex 1: mass -1 kg is negative"), std::string::npos) << e.what();
  }
}

TEST(PlyVertices, HeaderErrorsNameLineAndColumn) {
  const std::string f = "format ascii 1.0\n", v = "element vertex 1\nproperty float x\nproperty float y\n";
  const std::pair<std::string, std::string> cases[] = {
      {"plx\n", "t.ply:1:1: expected 'ply'"},
      {"", "t.ply:1:1: expected 'ply'"},
      {"ply\nformat ascii 2.0\n", "t.ply:2:14: expected version 1.0, found '2.0'"},
      {"ply\nformat binary 1.0\n", "t.ply:2:8: expected ascii, binary_little_endian or binary_big_endian"},
      {"ply\nformat ascii\n", "t.ply:2:13: expected 'format ascii|binary_little_endian|binary_big_endian 1.0'"},
      {"ply\n" + f + f, "t.ply:3:1: a second 'format' line"},
      {"ply\n" + f + "element vertex -3\n", "t.ply:3:16: expected the element count"},
      {"ply\n" + f + "element vertex 8 9\n", "t.ply:3:18: expected the end of the line"},
      {"ply\n" + f + "property float x\n", "t.ply:3:1: a 'property' line before any 'element' line"},
      {"ply\n" + f + v + "property flaot z\n", "t.ply:6:10: expected a PLY type"},
      {"ply\n" + f + v + "property list float int z\n", "t.ply:6:15: expected an integer type for the list's length"},
      {"ply\n" + f + v + "property float y\n", "t.ply:6:16: property 'y' is declared twice"},
      {"ply\n" + f + v, "t.ply:6:1: the file ends before 'end_header'"},
      {"ply\n" + v + "end_header\n", "t.ply:5:1: expected a 'format' line before 'end_header'"},
      {"ply\n" + f + v + "end_header\n", "t.ply:3: the vertex element has no property 'z'"},
      {"ply\n" + f + v + "property list uchar float z\nend_header\n", "t.ply:3: the vertex element declares 'z' as a list"},
      {"ply\n" + f + "element face 1\nend_header\n", "t.ply: the header declares no 'vertex' element"},
      {"ply\n" + f + "element vertex 0\nproperty float x\nproperty float y\nproperty float z\nend_header\n",
       "t.ply:3: the vertex element is empty"},
      {"ply\n" + std::string(5000, 'a'), "t.ply:2:1: a header line longer than 4096 characters"},
  };
  for (const auto& [text, expected] : cases) EXPECT_NE(error_of(text).find(expected), std::string::npos)
      << "expected: " << expected << "\ngot: " << error_of(text);
}

TEST(PlyVertices, DataErrorsNameTheVertex) {
  const std::string le = binary_corners(false);
  // Cut inside vertex 5 (each vertex record is 4 + 2 + 4 + 1 + 8 bytes).
  EXPECT_NE(error_of(le.substr(0, le.size() - 2 * 19 - 7)).find("t.ply: the data ends inside vertex 5 of 8 (a truncated"),
            std::string::npos);
  const std::size_t data = le.find("end_header\n") + 11;
  EXPECT_NE(error_of(le.substr(0, data + 10)).find("inside element 'material' record 0 (before the vertices) of 2"),
            std::string::npos);
  std::string a = ascii_corners();
  a.replace(a.find("\n1 -2 -3 1\r"), 11, "\n1 abc -3 1\r");  // vertex 1, on line 13
  EXPECT_NE(error_of(a).find("t.ply:13:3: vertex 1: expected a number for property 'y', found 'abc'"), std::string::npos)
      << error_of(a);
  auto with = [](const std::string& corner1) {
    std::string t = ascii_corners();
    return t.replace(t.find("\n1 -2 -3 1\r"), 11, "\n" + corner1 + "\r");
  };
  EXPECT_NE(error_of(with("1 -2 -3 nan")).find("vertex 1: mass nan is not finite"), std::string::npos);
  EXPECT_NE(error_of(with("1 -2 -3 1e999")).find("vertex 1: mass inf is not finite"), std::string::npos);
  EXPECT_EQ(parse(with("1 -2 -3 1e-999")).masses[1], 0.0);  // underflows to 0, which is allowed
  EXPECT_NE(error_of(with("1 inf -3 1")).find("vertex 1: position (1, inf, -3) is not finite"), std::string::npos);
  std::string zero = "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
                     "property uint8 mass\nend_header\n0 0 0 0\n1 1 1 0\n";
  EXPECT_NE(error_of(zero).find("t.ply: the vertex masses sum to 0 kg; expected a positive, finite total"),
            std::string::npos);
  // A list length of 255 is valid; the file then ends inside the skipped element.
  EXPECT_NE(error_of(std::string(le).insert(data, "\xff")).find("the data ends inside"), std::string::npos);
}

// Hostile bytes: every mutation of a valid file parses or throws InputError,
// quickly (forged counts and list lengths end at the end of the data).
TEST(PlyVertices, MutatedFilesParseOrFailCleanly) {
  for (const std::string& base : {binary_corners(false), binary_corners(true), ascii_corners()}) {
    UnitRandom rnd(7);
    for (int trial = 0; trial < 3000; ++trial) {
      std::string t = base;
      for (int k = 0, n = 1 + int(4 * rnd()); k < n; ++k) {
        const std::size_t at = std::size_t(rnd() * double(t.size()));
        const double what = rnd();
        if (what < 0.6) t[at] = char(int(256 * rnd()));
        else if (what < 0.8) t.erase(at, 1 + std::size_t(8 * rnd()));
        else t.insert(at, std::string(1, "0123456789 \n-e."[int(15 * rnd())]));
      }
      try {
        const scene::PlyVertices v = parse(t);
        EXPECT_FALSE(v.positions.empty());
        for (const auto& p : v.positions) EXPECT_TRUE(p.allFinite());
      } catch (const InputError&) {
      }
    }
  }
}

}  // namespace
