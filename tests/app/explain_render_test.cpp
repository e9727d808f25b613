// Explanatory renders end to end: frame ranges match the full run byte for
// byte, and time_scale / slow motion set the frame count.
#include <cstdio>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace {

class ExplainCli : public Cli {};

TEST_F(ExplainCli, FrameRangeOfLaidOutViewsIsByteIdenticalToTheFullRun) {
  const std::string scene = "'" + (kSource / "tests/app/data/tiny_explained.toml").string() + "'";
  ASSERT_EQ(run("render " + scene + " -o '" + dir_.string() + "/full' --progress none").code, 0);
  const Result r = run("render " + scene + " -o '" + dir_.string() + "/part' --frames 9:11 --progress none");
  ASSERT_EQ(r.code, 0) << r.err;
  // The title card's hold 0.3 s (3 frames), then 0.2 s at half speed (4 frames),
  // 0.1 s at quarter speed (4), 0.3 s at half speed (6): 18 frames.
  EXPECT_TRUE(fs::exists(dir_ / "full" / "frame_000017.png"));
  EXPECT_FALSE(fs::exists(dir_ / "full" / "frame_000018.png"));
  for (int k = 9; k <= 11; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06d.png", k);
    const std::string a = slurp(dir_ / "full" / name), b = slurp(dir_ / "part" / name);
    ASSERT_FALSE(a.empty());
    EXPECT_TRUE(a == b) << name << " differs between the full run and --frames 9:11";
  }
  EXPECT_NE(slurp(dir_ / "full" / "frame_000009.png"), slurp(dir_ / "full" / "frame_000010.png"));
}

}  // namespace
