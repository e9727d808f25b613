#include <gtest/gtest.h>

#include <cstdio>

#include "io/frame_files.hpp"

namespace tumble::io {
namespace {

TEST(FrameFiles, NamesAreSixDigitsAndRecognised) {
  EXPECT_EQ(frame_path("out", 0), std::filesystem::path("out/frame_000000.png"));
  EXPECT_EQ(frame_path("out", 123456).filename(), "frame_123456.png");
  for (long k : {0L, 7L, 999999L}) EXPECT_TRUE(is_frame_file(frame_path("d", k).filename().string())) << k;
  // The ffmpeg input pattern names the same files.
  char name[32];
  std::snprintf(name, sizeof name, kFramePattern, 42);
  EXPECT_EQ(frame_path("d", 42).filename(), name);
}

TEST(FrameFiles, OtherNamesAreNotFrames) {
  for (const char* n : {"frame_00001.png", "frame_0000001.png", "frame_00000a.png", "frame_000001.png.tmp-1",
                        "frame_000001.jpg", "xframe_00001.png", "manifest.json"})
    EXPECT_FALSE(is_frame_file(n)) << n;
}

TEST(FrameFiles, IndexIsReadBackFromTheName) {
  for (long k : {0L, 7L, 120L, 999999L}) EXPECT_EQ(frame_index(frame_path("d", k).filename().string()), k) << k;
  EXPECT_EQ(frame_index("frame_000042.png"), 42);
}

TEST(FrameFiles, IndexOfOtherNamesIsNothing) {
  for (const char* n : {"frame_00001.png", "frame_0000001.png", "frame_00000a.png", "frame_-00001.png",
                        "frame_000001.png.tmp-1", "frame_000001.jpg", "xframe_00001.png", "manifest.json", ""})
    EXPECT_EQ(frame_index(n), std::nullopt) << n;
}

}  // namespace
}  // namespace tumble::io
