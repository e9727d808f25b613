// `tumble info` lists each body's flips (the events "flip N"
// counts) and the frames with the simulated time each shows.
#include <string>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace {

class InfoCli : public Cli {};

// `tumble info` lists the flips and the frames with the time each shows. As
// dzhanibekov_explained declares them: 1/8 speed to 4.5 s, then real speed to 20.5 s; 30 fps × (3 s
// title + 18.6 (the sphere's build-up and caption 1) + 2 + 4 + 3 + 12 + 6 s holds + 4.5 s × 8 + 16.5 s) = 3033 frames
// and the last; flip 1's hold at flip 1 = 1.2934 s, from video 3 + 18.6 + 2 + 8 × 1.2934 = 33.947 s (frame 1019);
// the e₂ spin flips every 2.3898 s, the e₁ and e₃ spins never.
TEST_F(InfoCli, ListsFlipsAndTheFramesClock) {
  const Result r = run("info " + scene("dzhanibekov_explained.toml"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("flips (e2 ⊥ L)     1.2934, 3.6832, 6.0730, 8.4628, 10.8526, 13.2424, 15.6322, 18.0220, 20.4118 s in 21 s"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("flips (e2 ⊥ L)     none in 21 s"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("frames 3034 at 30 fps (video 101.1 s;"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("2358-2852   video  78.600-95.067  s  t = 4.5000-20.9667 s  real time"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("2853-3033   video  95.100-101.100 s  hold, t = 21.0000 s"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("0-89     video   0.000-2.967   s  title card, t = 0 s"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("648-707    video  21.600-23.567  s  t = 0.0000-0.2458 s  ×1/8"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1019-1138   video  33.967-37.933  s  hold, t = 1.2934 s"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("t = 0.2500-1.2917 s  ×1/8"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("hold, t = 3.7332 s"), std::string::npos) << r.out;
  const Result j = run("info --json " + scene("dzhanibekov_explained.toml"));
  ASSERT_EQ(j.code, 0) << j.err;
  EXPECT_NE(j.out.find("\"flip_times\": ["), std::string::npos) << j.out;
  EXPECT_NE(j.out.find("\"count\": 3034"), std::string::npos);
}

}  // namespace
