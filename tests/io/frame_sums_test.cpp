// frames.sums: what a frame must be to be kept (recorded, unchanged, decoding
// whole at the render's size), and which lines of the record count.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/frame_files.hpp"
#include "io/frame_sums.hpp"
#include "io/png.hpp"

namespace tumble::io {
namespace {
namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(::testing::TempDir()) / ("tumble_sums_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

Image grey(int w, int h) { return {w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h * 3, 128)}; }

TEST(FrameSums, AFrameIsKeptOnlyAtTheRendersWidthAndHeight) {
  const fs::path dir = fresh_dir("size");
  const fs::path f = frame_path(dir, 0);
  write_png_atomic(f, grey(16, 12));
  record_frame(f);
  const auto sums = read_frame_sums(dir);
  EXPECT_EQ(check_frame(f, sums, 16, 12), "");
  EXPECT_EQ(check_frame(f, sums, 16, 13), "16x12, expected 16x13") << "right width, wrong height";
  EXPECT_EQ(check_frame(f, sums, 17, 12), "16x12, expected 17x12") << "wrong width, right height";
  EXPECT_EQ(check_frame(frame_path(dir, 1), sums, 16, 12), "missing");
  fs::remove_all(dir);
}

TEST(FrameSums, ATornOrMalformedLineIsNoRecord) {
  const fs::path dir = fresh_dir("lines");
  {
    std::ofstream out(dir / kFrameSumsName, std::ios::binary);
    out << "frame_000000.png 10 0123456789abcdef\n"   // whole
        << "frame_000001.png 10 0123456789abcde\n"    // 15 hex digits
        << "frame_000002.png 10 0123456789abcdef0\n"  // 17
        << "frame_000003.png 10 0123456789abcdef";    // no newline: a kill cut it
  }
  const auto sums = read_frame_sums(dir);
  ASSERT_EQ(sums.size(), 1u);
  EXPECT_EQ(sums.count("frame_000000.png"), 1u);
  EXPECT_EQ(sums.at("frame_000000.png").size, 10u);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tumble::io
