// Absurd but legal shapes, round two: meshes that made the fill slow or its
// mass silently wrong, and sizes whose messages misled. Each case failed on
// the code before its fix. None needs GL.
#include <sys/stat.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <regex>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace {

using Triangle = std::array<std::array<float, 3>, 3>;

/// The unit cube's faces from `at`, two triangles each, outward; `open` leaves out the top (z = 1).
std::vector<Triangle> cube(std::array<float, 3> at, bool open = false) {
  const float q[6][4][3] = {{{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}}, {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}},
                            {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}}, {{1, 1, 0}, {0, 1, 0}, {0, 1, 1}, {1, 1, 1}},
                            {{0, 1, 0}, {0, 0, 0}, {0, 0, 1}, {0, 1, 1}}, {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
  std::vector<Triangle> out;
  for (int f = 0; f < (open ? 5 : 6); ++f) {
    auto p = [&](int k) {
      return std::array<float, 3>{q[f][k][0] + at[0], q[f][k][1] + at[1], q[f][k][2] + at[2]};
    };
    out.push_back({p(0), p(1), p(2)});
    out.push_back({p(0), p(2), p(3)});
  }
  return out;
}

class HostileShape : public Cli {
 protected:
  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return dir_ / name;
  }
  void write_stl(const std::string& name, const std::vector<Triangle>& tris) const {
    std::string b(80, '\0');
    const auto u32 = static_cast<std::uint32_t>(tris.size());
    b.append(reinterpret_cast<const char*>(&u32), 4);
    for (const Triangle& t : tris) {
      b.append(12, '\0');  // normal
      for (const auto& p : t) b.append(reinterpret_cast<const char*>(p.data()), 12);
      b.append(2, '\0');
    }
    write(name, b);
  }
  Result info(const std::string& body, int seconds = 20) const {
    return bounded("info '" + write("s.toml", "name = \"s\"\n[[bodies]]\n" + body + "\n").string() + "'", seconds);
  }
};

TEST_F(HostileShape, OverlappingCubesAreReportedAndWeighedAsTheirUnion) {
  // Two closed unit cubes, the second moved by (0.5, 0.5, 0.5): union 2 - 1/8 = 1.875 m³.
  std::vector<Triangle> tris = cube({0, 0, 0});
  for (const Triangle& t : cube({0.5f, 0.5f, 0.5f})) tris.push_back(t);
  write_stl("two.stl", tris);
  const Result r = info("shape = { type = \"mesh\", file = \"two.stl\", density = 1000 }");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("two.stl: the surface intersects itself"), std::string::npos) << r.err;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(mass +([0-9.e+]+) kg)"))) << r.out;
  EXPECT_NEAR(std::stod(m[1]), 1875, 1875 * 0.02) << "2000 kg is the two cubes counted apart";
}

TEST_F(HostileShape, AFillThatWouldTakeMinutesStopsNamingTheMeshAndTheResolution) {
  // 100 open cubes lying on each other: 55 kB, and no tree node is ever far from a point.
  std::vector<Triangle> tris;
  for (int k = 0; k < 100; ++k)
    for (const Triangle& t : cube({0, 0, 0}, true)) tris.push_back(t);
  write_stl("stacked.stl", tris);
  const Result r = info("shape = { type = \"mesh\", file = \"stacked.stl\", resolution = 60, density = 1000 }", 120);
  EXPECT_EQ(r.code, 2) << r.err;  // 137: still working after 120 s
  EXPECT_NE(r.err.find("stacked.stl: the volume fill at resolution 60 stopped"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("lower the resolution"), std::string::npos) << r.err;
}

TEST_F(HostileShape, AnOpenMeshsAmbiguousShareIsAShareOfItsPoints) {
  std::vector<Triangle> tris = cube({0, 0, 0});
  tris.resize(8);  // two faces gone
  write_stl("open.stl", tris);
  const Result r = info("shape = { type = \"mesh\", file = \"open.stl\", density = 1000 }");
  EXPECT_EQ(r.code, 2) << r.err;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.err, m, std::regex(R"(ambiguous \(between 0.25 and 0.75\) at ([0-9.e+]+) %)"))) << r.err;
  EXPECT_LE(std::stod(m[1]), 100) << r.err;
}

TEST_F(HostileShape, ExtremeSizesSayWhatIsWrongNotNanOrEmpty) {
  Result r = info("shape = { type = \"t_handle\", handle_length = 1, stem_length = 1, thickness = 1e-300, "
                  "resolution = 1, mass = 1 }");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(r.err.find("nan"), std::string::npos) << r.err;  // was "mass -nan kg"
  EXPECT_NE(r.err.find("body 'body0': all particles are (nearly) collinear"), std::string::npos) << r.err;
  r = info("shape = { type = \"ellipsoid\", semi_axes = [1e308, 1e308, 1e308], mass = 1 }");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(r.err.find("empty"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("overflow"), std::string::npos) << r.err;
  r = info("shape = { type = \"cylinder\", radius = 1e-300, length = 1, mass = 1 }");
  EXPECT_EQ(r.code, 2) << r.err;  // was "lower the resolution", which no resolution helps
  EXPECT_NE(r.err.find("length / diameter = 5e+299"), std::string::npos) << r.err;
}

TEST_F(HostileShape, TinyPlyMassesRescaledToAShapeMassStayFinite) {
  write("tiny.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                    "property double mass\nend_header\n1 0 0 1e-320\n-1 0 0 1e-320\n0 1 0 2e-320\n0 0 1 2e-320\n");
  const Result r = info("shape = { type = \"mesh\", file = \"tiny.ply\", fill = \"vertices\", mass = 6 }");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.find("inf"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("mass              6 kg"), std::string::npos) << r.out;
}

TEST_F(HostileShape, AFifoAsAMeshSaysWhatItIs) {
  ASSERT_EQ(::mkfifo((dir_ / "m.stl").c_str(), 0644), 0);
  const Result r = info("shape = { type = \"mesh\", file = \"m.stl\", density = 1000 }");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("m.stl: mesh file is a FIFO (named pipe), not a regular file"), std::string::npos) << r.err;
}

TEST_F(HostileShape, AnObjFaceOfTensOfThousandsOfCornersIsRefusedAtOnce) {
  // Nine corners of a disc, visited over and over: the line (64 000 characters) is under the line cap.
  std::string obj;
  for (int k = 0; k < 9; ++k)
    obj += "v " + std::to_string(std::cos(k * 0.7)) + " " + std::to_string(std::sin(k * 0.7)) + " 0\n";
  obj += "f";
  for (int k = 0; k < 32000; ++k) obj += " " + std::to_string(1 + k % 9);
  write("disc.obj", obj + "\n");
  const Result r = info("shape = { type = \"mesh\", file = \"disc.obj\", fill = \"surface\", mass = 1 }");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("a face of 32000 corners"), std::string::npos) << r.err;
}

}  // namespace
