// `tumble` end to end: output formats, exit codes, atomic CSV.
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_fixture.hpp"

namespace fs = std::filesystem;

namespace {

constexpr const char* kHeader =
    "t,body,cx,cy,cz,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,Lx,Ly,Lz,energy,wbx,wby,wbz,axis1_L,axis2_L,axis3_L";

TEST_F(Cli, Version) {
  const Result r = run("--version");
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.out.rfind("tumble ", 0), 0u) << r.out;
}

TEST_F(Cli, SimulateWritesHeaderAndEndsAtDuration) {
  const fs::path csv = dir_ / "ref.csv";
  const Result r = run("simulate " + scene("reference.toml") + " --csv '" + csv.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto l = lines(slurp(csv));
  ASSERT_EQ(l.size(), 1u + 301u);  // header + frames k/30 for k = 0..300
  EXPECT_EQ(l[0], kHeader);
  const auto first = split(l[1]), last = split(l.back());
  ASSERT_EQ(first.size(), 25u);
  EXPECT_EQ(first[0], "0");
  EXPECT_EQ(first[1], "reference");
  EXPECT_EQ(last[0], "10");
  EXPECT_EQ(first[15], "0.01");  // L = I ω_body at identity orientation: (0.01, 20, 0.03)
  EXPECT_EQ(first[16], "20");
  EXPECT_NEAR(std::stod(first[18]), 100.0002, 1e-10);  // energy ½ Σ I ω²
  // splitting: bounded energy error, O(dt²): |dE/E| 4.3e-6 at dt = 1 ms with
  // the 3,2,1,2,3 order (2.2e-6 with the old 1,2,3,2,1, whose orientation
  // error was 9x larger); core's conservation tests pin the figures.
  EXPECT_NEAR(std::stod(last[18]), 100.0002, 1e-3);
  // ω in the cloud's axes starts as the scene's omega_body; axis 2 starts
  // atan2(|(0.01, 0.03)|, 20) from L, axis 1 and 3 close to a right angle.
  EXPECT_NEAR(std::stod(first[19]), 0.01, 1e-12);
  EXPECT_NEAR(std::stod(first[20]), 10.0, 1e-12);
  EXPECT_NEAR(std::stod(first[21]), 0.01, 1e-12);
  EXPECT_NEAR(std::stod(first[23]), std::atan2(std::hypot(0.01, 0.03), 20.0), 1e-12);
  EXPECT_NEAR(std::stod(first[22]), std::acos(0.01 / std::sqrt(0.01 * 0.01 + 400 + 0.03 * 0.03)), 1e-12);
  // The flip: the intermediate axis turns from along L to against it (≈ π) and
  // back; ω_body's y component changes sign with it.
  double max_angle2 = 0, min_wby = 1e9;
  for (std::size_t i = 1; i < l.size(); ++i) {
    const auto f = split(l[i]);
    max_angle2 = std::max(max_angle2, std::stod(f[23]));
    min_wby = std::min(min_wby, std::stod(f[20]));
  }
  EXPECT_GT(max_angle2, 3.0);
  EXPECT_LT(min_wby, -9.0);
  for (const auto& e : fs::directory_iterator(dir_))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << "temp file left: " << e.path();
}

TEST_F(Cli, SimulateOverridesAndEvery) {
  const fs::path csv = dir_ / "every.csv";
  const Result r = run("simulate " + scene("stable_spin.toml") + " --csv '" + csv.string() +
                    "' --method rk4 --dt 0.01 --duration 1.05 --every 10");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto l = lines(slurp(csv));
  // t = 0, 0.1, ..., 1.0, then the final 1.05: 12 samples × 3 bodies.
  ASSERT_EQ(l.size(), 1u + 12u * 3u);
  EXPECT_EQ(split(l[4])[0], "0.10000000000000001");
  for (std::size_t k = l.size() - 3; k < l.size(); ++k) EXPECT_EQ(split(l[k])[0], "1.05");
  EXPECT_EQ(split(l.back())[1], "major");
}

// auto with a tolerance says what it picked and why, and lists the candidates in info.
TEST_F(Cli, AutoToleranceSaysWhatItPicked) {
  const fs::path csv = dir_ / "thruster.csv";
  const Result r = run("simulate " + scene("thruster.toml") + " --csv '" + csv.string() + "' --duration 3");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("body 'satellite': auto picked "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("<= tolerance 1e-06"), std::string::npos) << r.err;
  EXPECT_EQ(lines(slurp(csv)).size(), 1u + 91u);  // t = 0, 1/30, ..., 3
  const Result info = run("info " + scene("thruster.toml"));
  ASSERT_EQ(info.code, 0) << info.err;
  EXPECT_NE(info.out.find("<- picked"), std::string::npos) << info.out;
  // A torqued body gets dop853 at rtol = tolerance/10 without pilot runs: one candidate, priced.
  EXPECT_NE(info.out.find("dop853 "), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("not priced (no pilot)"), std::string::npos) << info.out;
  // docs/methods.md shows this block as info prints it (scripts/doc_figures.sh writes it).
  const std::string readme = slurp(kSource / "docs" / "methods.md");
  const std::size_t b = readme.find("<!-- BEGIN info:thruster -->\n"), e = readme.find("<!-- END info:thruster -->");
  ASSERT_TRUE(b != std::string::npos && e != std::string::npos && b < e) << "docs/methods.md: no info:thruster block";
  int shown = 0;
  for (const std::string& l : lines(readme.substr(b, e - b)))
    if (l.rfind("    ", 0) == 0) {
      ++shown;
      EXPECT_NE(info.out.find("  " + l.substr(4) + "\n"), std::string::npos)
          << "docs/methods.md's info:thruster line\n" << l << "\nis not what info prints; run scripts/doc_figures.sh";
    }
  EXPECT_GE(shown, 2);
  // The tolerance picks dt: a --dt on top is refused; --method takes over and drops it.
  EXPECT_EQ(run("simulate " + scene("thruster.toml") + " --csv '" + csv.string() + "' --dt 0.01").code, 2);
  const Result named = run("simulate " + scene("thruster.toml") + " --csv '" + csv.string() + "' --method rk4 --dt 0.01 --duration 1");
  EXPECT_EQ(named.code, 0) << named.err;
  EXPECT_EQ(named.err.find("auto picked"), std::string::npos) << named.err;
}

TEST_F(Cli, InfoJsonForTheReferenceScene) {
  const Result r = run("info " + scene("reference.toml") + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j.at("bodies").size(), 1u) << r.out;
  const auto& b = j["bodies"][0];
  using V = std::vector<double>;
  using M = std::vector<V>;
  EXPECT_EQ(b.at("name"), "reference");
  EXPECT_EQ(b.at("mass").get<double>(), 3);
  EXPECT_EQ(b.at("com").get<V>(), V({0, 0, 0}));
  EXPECT_EQ(b.at("inertia").get<M>(), M({{1, 0, 0}, {0, 2, 0}, {0, 0, 3}}));
  EXPECT_EQ(b.at("principal_moments").get<V>(), V({1, 2, 3}));
  EXPECT_EQ(b.at("principal_axes").get<M>(), M({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}));
  EXPECT_EQ(b.at("box").at("center").get<V>(), V({0, 0, 0}));
  EXPECT_EQ(b.at("box").at("half_extents").get<V>(), V({1, 1, 0}));
}

TEST_F(Cli, InfoTextNamesEveryBody) {
  const Result r = run("info " + scene("stable_spin.toml"));
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* b : {"body minor", "body intermediate", "body major"}) EXPECT_NE(r.out.find(b), std::string::npos);
}

TEST_F(Cli, InputErrorsExitWith2) {
  const fs::path broken = kSource / "tests/scene/broken/negative_dt.toml";
  Result r = run("simulate '" + broken.string() + "' --csv '" + (dir_ / "x.csv").string() + "'");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find(broken.string() + ":3:6: error: simulation.dt:"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "x.csv"));
  EXPECT_EQ(run("info '" + (dir_ / "missing.toml").string() + "'").code, 2);
  EXPECT_EQ(run("simulate " + scene("reference.toml") + " --csv '" + (dir_ / "x.csv").string() + "' --method rk5").code, 2);
  EXPECT_EQ(run("simulate " + scene("reference.toml") + " --csv '" + (dir_ / "x.csv").string() + "' --dt 20").code, 2);
  EXPECT_EQ(run("simulate " + scene("reference.toml")).code, 2);  // --csv is required
  EXPECT_EQ(run("frobnicate").code, 2);
}

TEST_F(Cli, DivergenceExits3AndKeepsRows) {
  const fs::path csv = dir_ / "d.csv";
  const Result r = run("simulate '" + (kSource / "tests/app/data/diverges_under_euler.toml").string() + "' --csv '" +
                    csv.string() + "'");
  EXPECT_EQ(r.code, 3);
  EXPECT_NE(r.err.find("diverged at t="), std::string::npos) << r.err;
  // The energy-balance guard stops this run at its first step (it
  // used to run on until the momenta overflowed): the row at t = 0 is kept.
  const auto l = lines(slurp(csv));
  ASSERT_GE(l.size(), 2u);
  EXPECT_EQ(l[0], kHeader);
  EXPECT_EQ(split(l[1])[0], "0");
  EXPECT_NE(r.err.find("diverged at t=0.1 s, step 1"), std::string::npos) << r.err;
}

// A forced body's blow-up (damping only removes energy) is caught by the energy
// balance, not only non-finite numbers; the coarse step is warned about first.
TEST_F(Cli, DampedBlowUpExits3WithTimeStepBodyAndMethod) {
  const fs::path csv = dir_ / "damped.csv";
  const Result r = run("simulate '" + (kSource / "tests/app/data/damped_blowup_euler.toml").string() + "' --csv '" +
                       csv.string() + "'");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("warning: body 'reference': dt = 0.5 s"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("diverged at t=0.5 s, step 1, body 'reference', method euler"), std::string::npos) << r.err;
  const auto l = lines(slurp(csv));
  ASSERT_EQ(l.size(), 1u + 15u);  // frames k/30 for t < 0.5 s, as computed before the failure
  EXPECT_EQ(split(l[1])[0], "0");
}

TEST_F(Cli, UnwritableCsvIsAnIoError) {
  const Result r = run("simulate " + scene("reference.toml") + " --csv '" + (dir_ / "no/such/dir/x.csv").string() + "'");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("no/such/dir"), std::string::npos) << r.err;
}

// A PLY point cloud with per-vertex masses (kg): info reports them, in text and
// JSON; a negative mass exits 2 naming the file and the vertex.
TEST_F(Cli, InfoShowsPlyVertexMasses) {
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                             "property float z\nproperty float mass\nend_header\n";
  std::ofstream(dir_ / "t.ply") << header << "0 0 0 1\n1 0 0 2\n0 1 0 3\n0 0 1 4\n";
  std::ofstream(dir_ / "t.toml") << "[[bodies]]\nshape = { type = \"mesh\", file = \"t.ply\", fill = \"vertices\" }\n";
  const Result text = run("info '" + (dir_ / "t.toml").string() + "'");
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("masses          per vertex, the PLY's `mass` property (sum 10 kg)"), std::string::npos)
      << text.out;
  const Result json = run("info '" + (dir_ / "t.toml").string() + "' --json");
  ASSERT_EQ(json.code, 0) << json.err;
  const auto b = nlohmann::json::parse(json.out).at("bodies").at(0);
  EXPECT_EQ(b.at("meshes").at(0).at("file_mass").get<double>(), 10.0);
  EXPECT_EQ(b.at("mass").get<double>(), 10.0);
  // About c = (0.2, 0.3, 0.4) m: diag(7, 6, 5) about the origin − 10 kg (|c|² I − c cᵀ).
  const auto J = b.at("inertia").get<std::vector<std::vector<double>>>();
  const double expected[3][3] = {{4.5, 0.6, 0.8}, {0.6, 4.0, 1.2}, {0.8, 1.2, 3.7}};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(J[i][k], expected[i][k], 1e-12) << i << k;
  std::ofstream(dir_ / "t.ply") << header << "0 0 0 1\n1 0 0 2\n0 1 0 -3\n0 0 1 4\n";
  const Result bad = run("info '" + (dir_ / "t.toml").string() + "'");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("t.ply: vertex 2: mass -3 kg is negative"), std::string::npos) << bad.err;
}

// The README's scene is a scene, and makes what the README says it makes:
// 181 frames, flips at 1.8 s and 5.1 s (its picture: scripts/explain_frames.sh).
TEST_F(Cli, ReadmeSceneIsAValidSceneThatFlipsWhereTheReadmeSays) {
  const std::string readme = slurp(kSource / "README.md");
  const std::size_t b = readme.find("```toml\n"), e = readme.find("```", b + 8);
  ASSERT_TRUE(b != std::string::npos && e != std::string::npos) << "README.md: no toml block";
  const fs::path scene = dir_ / "flip.toml";
  std::ofstream(scene) << readme.substr(b + 8, e - b - 8);
  const Result r = run("info '" + scene.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "") << "the README's scene warns";
  EXPECT_NE(r.out.find("flips (e2 \u22a5 L)     1.7999, 5.0887 s in 6 s"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("frames 181 at 30 fps"), std::string::npos) << r.out;
  EXPECT_NE(readme.find("flips over at t = 1.8 s and back at 5.1 s"), std::string::npos);
  EXPECT_NE(readme.find("`out/flip/frame_000000.png` \u2026 `frame_000180.png`"), std::string::npos);
}

}  // namespace
