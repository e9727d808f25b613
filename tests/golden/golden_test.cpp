// Golden images and golden physics of every shipped scene, determinism of the
// renderer, and the comparison itself (library and `tumble compare`/`golden`).
// TUMBLE_UPDATE_GOLDENS=1 turns the scene tests into `tumble golden --update`.
#include <algorithm>
#include <cstdlib>
#include <tuple>

#include <gtest/gtest.h>

#include "run/frame_renderer.hpp"
#include "compose/frame_builder.hpp"
#include "scene/frame_runs.hpp"
#include "cli_fixture.hpp"
#include "golden/compare.hpp"
#include "golden/trajectory.hpp"
#include "io/frame_files.hpp"
#include "io/png.hpp"
#include "scene/scene.hpp"

namespace {

class GoldenCli : public Cli {};

struct GoldenScene {
  const char* name;  ///< scenes/<name>.toml, goldens in tests/golden/<name>/
  const char* at;    ///< frame times (k/30 s): early, middle, late
  const char* select = "--at";  ///< or "--frames": `at` lists frame numbers
};

// Times are frame times (k/30 s for the classic scenes, which render at
// 30 fps); the last one bounds the simulation (fixed camera) and the trajectory.
const GoldenScene kScenes[] = {
    {"dzhanibekov", "0.5,4,12"},   {"methods_compare", "0.78,6,15"}, {"reference", "0.5,3,9"},
    {"stable_spin", "0.5,5,11"},   {"symmetric_top", "0.5,4,9"},    {"thrown_box", "0.2,0.9,1.6"},
    // The explanatory scenes' clocks have a title card and slow motion anchored
    // to flips: their goldens are frames (`tumble info` lists what each shows):
    // the title card, the stop at (or just after) the first flip, and a later
    // moment (dzhanibekov_explained: also its sphere half built up (frame 470), the last frame of its end
    // hold's views, the sphere turned (2298), and the closing side by side at flip 3 (2345); tennis_racket: the why sphere's 1 s stop, 1090).
    {"dzhanibekov_explained", "40,470,1126,2298,2345", "--frames"}, {"poinsot", "0.5,3,7"},
    {"tennis_racket", "40,600,1090", "--frames"},
};

bool updating() {
  const char* e = std::getenv("TUMBLE_UPDATE_GOLDENS");
  return e && std::string(e) == "1";
}

std::string golden_cmd(const GoldenScene& g, const std::string& extra, const std::string& report_suffix) {
  return "golden " + ("'" + (kSource / "scenes" / (std::string(g.name) + ".toml")).string() + "'") + " " + g.select + " " + g.at +
         " --dir '" + (kSource / "tests/golden" / g.name).string() + "' --report '" + TUMBLE_GOLDEN_REPORT_DIR + "/" +
         g.name + report_suffix + "' " + extra + (updating() ? " --update" : "");
}

class Scenes : public GoldenCli, public testing::WithParamInterface<GoldenScene> {};

// Physics first: its own test, so a physics change shows up as one.
TEST_P(Scenes, Physics) {
  const Result r = run(golden_cmd(GetParam(), "--physics-only", "-physics"));
  EXPECT_EQ(r.code, 0) << r.out << r.err;
}

TEST_P(Scenes, Pixels) {
  const Result r = run(golden_cmd(GetParam(), "--aa msaa4,none,fxaa --width 320 --height 240", ""));
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  if (!updating()) {
    // Every frame in each of the three anti-aliasing modes, and the trajectory.
    const std::string at = GetParam().at;
    const long cases = 3 * (1 + std::count(at.begin(), at.end(), ',')) + 1;
    EXPECT_NE(r.out.find("all " + std::to_string(cases) + " cases pass"), std::string::npos) << r.out;
  }
}

INSTANTIATE_TEST_SUITE_P(Golden, Scenes, testing::ValuesIn(kScenes),
                         [](const testing::TestParamInfo<GoldenScene>& i) { return std::string(i.param.name); });

// ---- determinism: identical bytes ----

// The overlay's |dE/E| is an error only where energy is conserved (gravity
// counts, as potential energy); a thruster's work is labelled, not reported.
TEST(Overlay, EnergyErrorOnlyWhereEnergyIsConserved) {
  auto overlay = [](const char* name) {
    const tumble::scene::Scene s = tumble::scene::load_scene(kSource / "scenes" / (std::string(name) + ".toml"));
    const std::vector<tumble::scene::Run> runs = tumble::scene::simulate_runs(s, 3, 30);
    const tumble::viz::DrawList dl = tumble::compose::FrameBuilder(s, runs, 30, 320, 240).build(2);
    std::string all;
    for (const auto& v : dl.views)
      for (const auto& t : v.texts) all += t.text + "\n";
    return all;
  };
  const std::string thruster = overlay("thruster"), thrown = overlay("thrown_box");
  EXPECT_NE(thruster.find("(forces do work)"), std::string::npos) << thruster;
  EXPECT_EQ(thruster.find("ΔE/E"), std::string::npos) << thruster;
  EXPECT_NE(thruster.find("dop853   rtol = 1e-07"), std::string::npos) << thruster;  // auto's pick (tolerance / 10), its real step
  EXPECT_NE(thrown.find("ΔE/E = "), std::string::npos) << thrown;  // signed: a gain shows as +
  EXPECT_NE(thrown.find("splitting   dt = 0.001 s"), std::string::npos) << thrown;
}

TEST(Determinism, SameFrameRenderedTwiceInOneProcess) {
  const tumble::scene::Scene s = tumble::scene::load_scene(kSource / "scenes/stable_spin.toml");
  const tumble::run::SceneFrames frames(s, 150);
  auto ctx = tumble::render::create_gl_context(tumble::render::default_gl_backend());
  for (const char* name : {"msaa4", "none", "fxaa"}) {
    tumble::scene::FrameSettings aa;
    aa.width = 320;
    aa.height = 240;
    ASSERT_TRUE(tumble::scene::parse_aa_case(name, aa)) << name;
    // Frame 150, another frame, frame 150 again (renderer state reused), then a fresh renderer.
    const auto a = frames.render(*ctx, {150, 30, 150}, aa);
    const auto b = frames.render(*ctx, {150}, aa);
    EXPECT_TRUE(a[0].rgb == a[2].rgb) << name;
    EXPECT_TRUE(a[0].rgb == b[0].rgb) << name;
    EXPECT_FALSE(a[0].rgb == a[1].rgb) << "frames 150 and 30 should differ";
  }
}

class DeterminismCli : public Cli {};

// llvmpipe splits the frame into tiles over LP_NUM_THREADS threads; the bytes must not depend on it.
TEST_F(DeterminismCli, LpNumThreadsOneAndTwoGiveIdenticalBytes) {
  for (const char* sc : {"dzhanibekov.toml", "methods_compare.toml"}) {
    std::string files[2];
    for (int threads = 1; threads <= 2; ++threads) {
      const std::string out = (dir_ / (std::string(sc) + ".t" + std::to_string(threads))).string();
      // Set in the child's environment only, before it creates its GL context.
      const std::string cmd = std::string("LP_NUM_THREADS=") + std::to_string(threads) + " '" + TUMBLE_BIN + "' render " +
                              scene(sc) + " --frames 120:120 --width 320 --height 240 --msaa 4 --video none --progress none -o '" +
                              out + "' >'" + out + ".log' 2>&1";
      ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd << "\n" << slurp(out + ".log");
      files[threads - 1] = slurp(tumble::io::frame_path(out, 120));
      ASSERT_FALSE(files[threads - 1].empty());
    }
    EXPECT_TRUE(files[0] == files[1]) << sc << ": LP_NUM_THREADS=1 and 2 differ";
  }
}
// Full run vs --frames range: tests/app/render_cli_test.cpp (RenderCli.FrameRangeIsByteIdenticalToTheFullRun).

// The golden path draws what `tumble render` draws (fixed and automatic camera).
TEST_F(DeterminismCli, GoldenFramesMatchTumbleRender) {
  if (updating()) GTEST_SKIP() << "updating goldens";
  for (const auto& [sc, frame, aa] : {std::tuple{"dzhanibekov", 270, "msaa4"}, std::tuple{"stable_spin", 150, "msaa4"},
                                     std::tuple{"dzhanibekov", 270, "fxaa"}}) {
    const std::string out = (dir_ / (std::string(sc) + aa)).string();
    const std::string aa_option = std::string(aa) == "fxaa" ? " --aa fxaa" : " --msaa 4";
    ASSERT_EQ(run("render " + scene((std::string(sc) + ".toml").c_str()) + " --frames " + std::to_string(frame) + ":" +
                  std::to_string(frame) + " --width 320 --height 240" + aa_option + " --video none --progress none -o '" +
                  out + "'")
                  .code,
              0);
    const std::string name = tumble::io::frame_path("", frame).string();
    char golden[96];
    std::snprintf(golden, sizeof golden, "%s_f%06d_%s.png", sc, frame, aa);
    const Result r = run("compare '" + out + "/" + name + "' '" + (kSource / "tests/golden" / sc / golden).string() + "'");
    EXPECT_EQ(r.code, 0) << r.out << r.err;
  }
}

// ---- the comparison ----

tumble::io::Image flat(int w, int h, std::uint8_t v) {
  return {w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h * 3, v)};
}

// The comparison itself on synthetic images: compare_test.cpp.

TEST(Trajectory, WithinToleranceAndPhysicsChanged) {
  const std::string h = std::string(tumble::io::trajectory_header()) + "\n";
  const std::string e = h + "0,b,1,2,3,1,0,0,0,0,0,0,0,0,0,0,0,0,5\n";
  EXPECT_TRUE(tumble::golden::compare_trajectories(h + "0,b,1.0000001,2,3,1,0,0,0,0,0,0,0,0,0,0,0,0,5\n", e).pass);
  const auto bad = tumble::golden::compare_trajectories(h + "0,b,1,2,3,1,0,0,0,0,0,0,0,0,0,0,0,0,5.0001\n", e);
  EXPECT_FALSE(bad.pass);
  EXPECT_NE(bad.summary.find("energy"), std::string::npos) << bad.summary;
  EXPECT_FALSE(tumble::golden::compare_trajectories(h, e).pass);  // fewer rows (a run diverged)
  EXPECT_FALSE(tumble::golden::compare_trajectories("x\n", e).pass);
}

// A golden trajectory edited on Windows has CRLF line endings; it is the same
// trajectory, so it compares equal to the LF file the run writes.
TEST(Trajectory, AWindowsEditedFileWithCrlfLineEndingsIsTheSameTrajectory) {
  const std::string row = "0,b,1,2,3,1,0,0,0,0,0,0,0,0,0,0,0,0,5";
  const std::string lf = std::string(tumble::io::trajectory_header()) + "\n" + row + "\n";
  const std::string crlf = std::string(tumble::io::trajectory_header()) + "\r\n" + row + "\r\n";
  const auto r = tumble::golden::compare_trajectories(lf, crlf);
  EXPECT_TRUE(r.pass) << r.summary;
  EXPECT_EQ(r.rows, 1);
  const auto back = tumble::golden::compare_trajectories(crlf, lf);
  EXPECT_TRUE(back.pass) << back.summary;
}

TEST_F(GoldenCli, CompareExitCodes) {
  auto w = [&](const char* n, const tumble::io::Image& img) {
    tumble::io::write_png_atomic(dir_ / n, img);
    return "'" + (dir_ / n).string() + "'";
  };
  auto img = flat(64, 48, 200);
  const std::string a = w("a.png", img);
  img.rgb[0] = 0;
  const std::string one = w("one.png", img);
  for (int i = 0; i < 64 * 10; ++i) img.rgb[static_cast<std::size_t>(i) * 3] = 0;
  const std::string many = w("many.png", img);
  const std::string other = w("other.png", flat(48, 64, 200));
  std::ofstream(dir_ / "junk.png") << "not a png";
  EXPECT_EQ(run("compare " + a + " " + a).code, 0);
  EXPECT_EQ(run("compare " + one + " " + a).code, 0);  // 1 of 3072 pixels: 3.3e-4 <= 5e-4
  Result r = run("compare " + many + " " + a + " --diff '" + (dir_ / "d.png").string() + "'");
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("640 of 3072 pixels"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(dir_ / "d.png"));
  r = run("compare " + other + " " + a);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("sizes differ"), std::string::npos) << r.out;
  r = run("compare '" + (dir_ / "junk.png").string() + "' " + a);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("junk.png"), std::string::npos) << r.err;
  EXPECT_EQ(run("compare '" + (dir_ / "nope.png").string() + "' " + a).code, 2);
  EXPECT_EQ(run("compare " + a + " " + a + " --max-delta 300").code, 2);
  EXPECT_EQ(run("compare " + a + " " + a + " --window 0").code, 2);
  EXPECT_EQ(run("compare " + a + " " + a + " --max-region -1").code, 2);
  EXPECT_EQ(run("compare " + a + " " + a + " --max-window-mean 256").code, 2);
}

// A 3x3 patch +60 (9 of 76800 pixels, under --max-fraction) fails by its region
// and its windowed mean; the figures and the outlined difference show where.
TEST_F(GoldenCli, CompareReportsTheLocalFigures) {
  auto img = flat(320, 240, 100);
  tumble::io::write_png_atomic(dir_ / "a.png", img);
  for (int y = 20; y < 23; ++y)
    for (int x = 30; x < 33; ++x) img.rgb[(static_cast<std::size_t>(y) * 320 + x) * 3 + 1] = 160;
  tumble::io::write_png_atomic(dir_ / "b.png", img);
  const std::string ab = "compare '" + (dir_ / "b.png").string() + "' '" + (dir_ / "a.png").string() + "'";
  Result r = run(ab + " --diff '" + (dir_ / "d.png").string() + "'");
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("fraction over 8:  0.000117 (limit 0.0005)\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("largest region:    9 px, box (30,20)-(32,22) 3x3 (limit 6)  FAIL"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("worst 9x9 mean:  6.67 levels"), std::string::npos) << r.out;
  const auto d = tumble::io::read_png(dir_ / "d.png");
  EXPECT_EQ(d.pixel(28, 18)[0], 255) << "yellow outline 2 px outside the region";
  EXPECT_EQ(d.pixel(31, 21)[1], 255) << "the region itself: 60 x 16 clamped";
  // Each limit is an option.
  EXPECT_EQ(run(ab + " --max-region 9 --max-window-mean 6.7").code, 0);
  EXPECT_EQ(run(ab + " --max-region 9 --window 3 --max-window-mean 59").code, 1);  // 3x3 mean = 60
}

const char* kTiny = TUMBLE_SOURCE_DIR "/tests/app/data/tiny_render.toml";

TEST_F(GoldenCli, MissingGoldenFailsAndIsNotCreated) {
  const std::string cmd = std::string("golden '") + kTiny + "' --at 0.1 --dir '" + (dir_ / "g").string() +
                          "' --report '" + (dir_ / "rep").string() + "' --height 48";
  const Result r = run(cmd + " --width 64");
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("MISSING"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::is_empty(dir_ / "g"));
  EXPECT_TRUE(fs::exists(dir_ / "rep/index.html"));
  // --update creates them; then the same check passes, and a changed size fails with a report.
  EXPECT_EQ(run(cmd + " --width 64 --update").code, 0);
  const Result ok = run(cmd + " --width 64");
  EXPECT_EQ(ok.code, 0) << ok.out << ok.err;
  EXPECT_FALSE(fs::exists(dir_ / "rep/index.html")) << "a passing run removes the stale report";
  const Result bad = run(cmd + " --width 48");
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.out.find("sizes differ"), std::string::npos) << bad.out;
  EXPECT_NE(bad.out.find((dir_ / "rep/index.html").string()), std::string::npos) << bad.out;
}

TEST_F(GoldenCli, ChangedImageWritesTheFourPicturesAndTheIndex) {
  const std::string cmd = std::string("golden '") + kTiny + "' --at 0.1 --dir '" + (dir_ / "g").string() +
                          "' --report '" + (dir_ / "rep").string() + "' --width 64 --height 48 --msaa 0";
  ASSERT_EQ(run(cmd + " --update").code, 0);
  const fs::path png = dir_ / "g" / "tiny_render_f000001_msaa0.png";
  ASSERT_TRUE(fs::exists(png)) << run("golden --help").out;
  EXPECT_NE(slurp(dir_ / "g" / "tiny_render_f000001_msaa0.json").find("\"gl_renderer\": \""), std::string::npos);
  auto img = tumble::io::read_png(png, tumble::ReadRole::own_output);  // edited in place below
  for (auto& v : img.rgb) v = static_cast<std::uint8_t>(255 - v);
  tumble::io::write_png_atomic(png, img);
  const Result r = run(cmd);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("FAIL"), std::string::npos) << r.out;
  for (const char* kind : {"actual", "expected", "diff", "mask"})
    EXPECT_TRUE(fs::exists(dir_ / "rep/img" / (std::string("tiny_render_f000001_msaa0.") + kind + ".png"))) << kind;
  const std::string html = slurp(dir_ / "rep/index.html");
  EXPECT_NE(html.find("img/tiny_render_f000001_msaa0.diff.png"), std::string::npos);
  EXPECT_NE(html.find("max delta"), std::string::npos);
}

// Times pick the nearest frame (within half a frame), as decimals or simple
// fractions; --frames takes frame numbers.
TEST_F(GoldenCli, TimesPickTheNearestFrameOrFrameNumbers) {
  const std::string base = std::string("golden '") + kTiny + "' --dir '" + (dir_ / "g").string() + "' --report '" +
                           (dir_ / "rep").string() + "' --width 32 --height 24 --msaa 0 --every 100";
  const Result made = run(base + " --at 1/10 --update");  // tiny_render: 10 fps
  ASSERT_EQ(made.code, 0) << made.out << made.err;
  EXPECT_TRUE(fs::exists(dir_ / "g" / "tiny_render_f000001_msaa0.png")) << made.out;
  for (const char* pick : {"--at 0.1", "--at 0.0999999", "--at 0.14", "--at 0.06", "--frames 1", "--at 1/10,0.1"}) {
    const Result r = run(base + " " + pick);
    EXPECT_EQ(r.code, 0) << pick << "\n" << r.out << r.err;
    EXPECT_NE(r.out.find("(frame 1)"), std::string::npos) << pick << "\n" << r.out;
  }
  for (const char* bad : {"--at -0.1", "--at 0.7", "--frames 7", "--frames 1.5", "--frames -1", "--at 1/0", "--at x",
                          "--at 0.1 --frames 1", ""}) {
    const Result r = run(base + " " + bad);
    EXPECT_EQ(r.code, 2) << "'" << bad << "'\n" << r.out << r.err;
  }
  EXPECT_NE(run(base + " --frames 7").err.find("last frame 6"), std::string::npos);
}

}  // namespace
