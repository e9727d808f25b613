// --frames A:B against a scene's frame count: the last frame is count - 1.
#include <gtest/gtest.h>

#include "base/error.hpp"
#include "run/frame_range.hpp"

namespace tumble::run {
namespace {

TEST(FrameRange, TheLastFrameIsCountMinusOneAndOnePastItIsRefused) {
  EXPECT_EQ(parse_frame_range("0:6", 7), (std::pair<long, long>{0, 6}));
  EXPECT_EQ(parse_frame_range("6:", 7), (std::pair<long, long>{6, 6}));
  EXPECT_EQ(parse_frame_range(":", 7), (std::pair<long, long>{0, 6}));
  for (const char* past : {"0:7", "7:7", "3:8"}) {
    try {
      (void)parse_frame_range(past, 7);
      ADD_FAILURE() << past << " of 7 frames was taken as valid";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("the scene has frames 0:6"), std::string::npos) << e.what();
    }
  }
}

TEST(FrameRange, MalformedRangesAreRefusedByName) {
  for (const char* bad : {"3", "a:2", "2:1", "-1:2", "1:2x"}) EXPECT_THROW((void)parse_frame_range(bad, 7), InputError) << bad;
}

}  // namespace
}  // namespace tumble::run
