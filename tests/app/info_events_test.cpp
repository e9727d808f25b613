// `tumble info` lists each body's flips (the events "flip N"
// counts) and the frames with the simulated time each shows.
#include <string>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace {

class InfoCli : public Cli {};

// `tumble info` lists the flips and the frames with the time each shows.
TEST_F(InfoCli, ListsFlipsAndTheFramesClock) {
  const Result r = run("info " + scene("dzhanibekov_explained.toml"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("flips (e2 ⊥ L)     1.3383, 3.4591 s in 4.5 s"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("frames 1711 at 30 fps"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("0-89     video   0.000-2.967   s  title card, t = 0 s"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("135-209    video   4.500-6.967   s  t = 0.0000-0.2467 s  ×1/10"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("575-694    video  19.167-23.133  s  hold, t = 1.5083 s"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("t = 0.5404-1.5071 s  ×1/8"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("hold, t = 3.5091 s"), std::string::npos) << r.out;
  const Result j = run("info --json " + scene("dzhanibekov_explained.toml"));
  ASSERT_EQ(j.code, 0) << j.err;
  EXPECT_NE(j.out.find("\"flip_times\": ["), std::string::npos) << j.out;
  EXPECT_NE(j.out.find("\"count\": 1711"), std::string::npos);
}

}  // namespace
