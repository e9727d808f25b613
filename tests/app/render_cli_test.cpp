// `tumble render` end to end: frames, manifest, frame ranges, divergence.
#include <gtest/gtest.h>

#include <tuple>

#include "cli_fixture.hpp"

namespace {

// Own suite name: the fixture header's anonymous namespace gives each file its own Cli class.
class RenderCli : public Cli {};

std::string data(const char* name) { return "'" + (kSource / "tests/app/data" / name).string() + "'"; }

TEST_F(RenderCli, RenderWritesEveryFrameAndACompleteManifest) {
  TUMBLE_NEED_GL();
  const Result r = run("render " + data("tiny_render.toml") + " -o '" + dir_.string() + "/full' --progress none");
  ASSERT_EQ(r.code, 0) << r.err;
  for (int k = 0; k <= 6; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06d.png", k);
    EXPECT_TRUE(fs::exists(dir_ / "full" / name)) << name;
  }
  EXPECT_FALSE(fs::exists(dir_ / "full" / "frame_000007.png"));
  const std::string manifest = slurp(dir_ / "full" / "manifest.json");
  EXPECT_NE(manifest.find("\"complete\": true"), std::string::npos) << manifest;
  EXPECT_NE(manifest.find("\"frame_count\": 7"), std::string::npos) << manifest;
  EXPECT_NE(manifest.find("\"gl_renderer\": \"llvmpipe"), std::string::npos) << manifest;
  for (const auto& e : fs::directory_iterator(dir_ / "full"))
    EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();
}

// The manifest names the anti-aliasing used. tiny_render.toml says msaa = 4
// (no aa key): 4x MSAA, as before `aa` existed; --msaa N alone means N
// samples (0: none), --quality low none, medium at most 2 samples.
TEST_F(RenderCli, ManifestNamesTheAntialiasing) {
  TUMBLE_NEED_GL();
  const std::tuple<const char*, const char*, int> cases[] = {
      {"", "msaa", 4},          {"--aa fxaa", "fxaa", 0},         {"--msaa 0", "none", 0},
      {"--quality low", "none", 0}, {"--quality medium", "msaa", 2}, {"--aa msaa --msaa 2", "msaa", 2}};
  int i = 0;
  for (const auto& [args, aa, samples] : cases) {
    const std::string out = dir_.string() + "/aa" + std::to_string(i++);
    const Result r = run("render " + data("tiny_render.toml") + " -o '" + out + "' --progress none " + args);
    ASSERT_EQ(r.code, 0) << args << r.err;
    const std::string manifest = slurp(fs::path(out) / "manifest.json");
    EXPECT_NE(manifest.find("\"aa\": \"" + std::string(aa) + "\""), std::string::npos) << args << "\n" << manifest;
    EXPECT_NE(manifest.find("\"msaa\": " + std::to_string(samples) + ","), std::string::npos) << args << "\n" << manifest;
  }
}

TEST_F(RenderCli, FrameRangeIsByteIdenticalToTheFullRun) {
  TUMBLE_NEED_GL();
  ASSERT_EQ(run("render " + data("tiny_render.toml") + " -o '" + dir_.string() + "/full' --progress none").code, 0);
  const Result r = run("render " + data("tiny_render.toml") + " -o '" + dir_.string() + "/part' --frames 3:5 --progress none");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "part" / "frame_000002.png"));
  for (int k = 3; k <= 5; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06d.png", k);
    const std::string a = slurp(dir_ / "full" / name), b = slurp(dir_ / "part" / name);
    ASSERT_FALSE(a.empty());
    EXPECT_TRUE(a == b) << name << " differs between the full run and --frames 3:5";
  }
  // Frames differ from each other (the body moves), so equality above means something.
  EXPECT_NE(slurp(dir_ / "full" / "frame_000003.png"), slurp(dir_ / "full" / "frame_000004.png"));
}

// The frames do not depend on the thread count (--jobs,
// TUMBLE_JOBS) nor on the GPU paths (PBO read-back one frame late, FXAA as
// a GL pass): each frame is finished from its own read-back alone.
TEST_F(RenderCli, FramesAreByteIdenticalWhateverTheJobs) {
  TUMBLE_NEED_GL();
  const std::string scene = data("tiny_render.toml") + " --aa fxaa --progress none -o '" + dir_.string();
  const Result one = run("render " + scene + "/one' --jobs 1", "TUMBLE_GPU_PATHS=none");
  ASSERT_EQ(one.code, 0) << one.err;
  const Result three = run("render " + scene + "/three' --jobs 3", "TUMBLE_GPU_PATHS=none");
  ASSERT_EQ(three.code, 0) << three.err;
  const Result env = run("render " + scene + "/env'", "TUMBLE_JOBS=2 TUMBLE_GPU_PATHS=pbo,fxaa");
  ASSERT_EQ(env.code, 0) << env.err;
  for (int k = 0; k <= 6; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06d.png", k);
    const std::string a = slurp(dir_ / "one" / name);
    ASSERT_FALSE(a.empty()) << name;
    EXPECT_TRUE(a == slurp(dir_ / "three" / name)) << name << " differs between --jobs 1 and --jobs 3";
    EXPECT_TRUE(a == slurp(dir_ / "env" / name)) << name << " differs with TUMBLE_JOBS=2 and the GPU paths";
  }
  EXPECT_NE(slurp(dir_ / "one" / "frame_000003.png"), slurp(dir_ / "one" / "frame_000004.png"));
  const std::string manifest = slurp(dir_ / "one" / "manifest.json");
  EXPECT_NE(manifest.find("\"gl_device\": \""), std::string::npos) << manifest;
  EXPECT_NE(manifest.find("\"hardware_gpu\": "), std::string::npos) << manifest;
  EXPECT_NE(run("render " + scene + "/bad' --jobs 0").code, 0);
  const Result bad_env = run("render " + scene + "/bad'", "TUMBLE_JOBS=many");
  EXPECT_EQ(bad_env.code, 2) << bad_env.err;
  EXPECT_NE(bad_env.err.find("TUMBLE_JOBS"), std::string::npos) << bad_env.err;
}

TEST_F(RenderCli, RenderRejectsABadFrameRange) {
  const Result r = run("render " + data("tiny_render.toml") + " -o '" + dir_.string() + "/x' --frames 5:99");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("frames 0:6"), std::string::npos) << r.err;
}

TEST_F(RenderCli, DivergedRenderKeepsFramesAndMarksManifestIncomplete) {
  TUMBLE_NEED_GL();
  const Result r = run("render " + data("diverges_under_euler.toml") + " -o '" + dir_.string() +
                       "/div' --width 64 --height 48 --video none --progress none");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("diverged at t="), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "div" / "frame_000000.png"));
  EXPECT_NE(slurp(dir_ / "div" / "manifest.json").find("\"complete\": false"), std::string::npos);
}

TEST_F(RenderCli, DampedBlowUpRenderExits3) {
  TUMBLE_NEED_GL();
  const Result r = run("render " + data("damped_blowup_euler.toml") + " -o '" + dir_.string() +
                       "/damped' --width 64 --height 48 --video none --progress none");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("diverged at t=0.5 s, step 1, body 'reference', method euler"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "damped" / "frame_000000.png"));
  EXPECT_NE(slurp(dir_ / "damped" / "manifest.json").find("\"complete\": false"), std::string::npos);
}

}  // namespace
