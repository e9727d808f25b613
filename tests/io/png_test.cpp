#include <algorithm>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "io/png.hpp"

namespace tumble::io {
namespace {
namespace fs = std::filesystem;

Image gradient(int w, int h) {
  Image img{w, h, std::vector<std::uint8_t>(std::size_t(w) * h * 3)};
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = img.rgb.data() + (std::size_t(y) * w + x) * 3;
      p[0] = std::uint8_t(x * 255 / std::max(w - 1, 1));
      p[1] = std::uint8_t(y * 255 / std::max(h - 1, 1));
      p[2] = std::uint8_t((x * 7 + y * 13) & 0xff);
    }
  }
  return img;
}

// Looks like a rendered frame: vertical sky gradient, flat-shaded shapes
// with soft edges.
Image frame_like(int w, int h) {
  Image img{w, h, std::vector<std::uint8_t>(std::size_t(w) * h * 3)};
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = img.rgb.data() + (std::size_t(y) * w + x) * 3;
      const double sky = 1.0 - 0.1 * y / h;
      p[0] = std::uint8_t(230 * sky);
      p[1] = std::uint8_t(236 * sky);
      p[2] = std::uint8_t(248 * sky);
      for (int k = 0; k < 12; ++k) {  // shaded discs
        const double cx = w * (0.1 + 0.07 * k), cy = h * (0.3 + 0.03 * k), r = 40.0 + 5 * k;
        const double d = std::hypot(x - cx, y - cy);
        if (d < r) {
          const double shade = 0.5 + 0.5 * (cx - x + cy - y) / (2 * r);
          p[0] = std::uint8_t(200 * shade);
          p[1] = std::uint8_t(std::min(255.0, 60 * shade + 20 * k));  // in range: a wider value is UB
          p[2] = std::uint8_t(40 + 10 * k);
        }
      }
    }
  }
  return img;
}

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(testing::TempDir()) / ("tumble_" + name + "_" +
                                                       std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(PngIo, RoundTripIsLosslessAndLeavesNoTempFiles) {
  const fs::path dir = fresh_dir("png_roundtrip");
  const Image img = gradient(97, 61);  // odd sizes catch stride mistakes
  const fs::path path = dir / "frame.png";
  write_png_atomic(path, img);
  const Image back = read_png(path);
  EXPECT_EQ(back.width, img.width);
  EXPECT_EQ(back.height, img.height);
  EXPECT_TRUE(back.rgb == img.rgb);
  for (const auto& entry : fs::directory_iterator(dir)) {
    EXPECT_EQ(entry.path().filename(), "frame.png") << "stray file " << entry.path();
  }
  fs::remove_all(dir);
}

TEST(PngIo, OverwritesExistingFile) {
  const fs::path dir = fresh_dir("png_overwrite");
  write_png_atomic(dir / "f.png", gradient(8, 8));
  write_png_atomic(dir / "f.png", gradient(16, 4));
  EXPECT_EQ(read_png(dir / "f.png").width, 16);
  fs::remove_all(dir);
}

TEST(PngIo, FailureNamesPathAndCleansUp) {
  const fs::path dir = fresh_dir("png_fail");
  const fs::path bad = dir / "missing_subdir" / "frame.png";
  try {
    write_png_atomic(bad, gradient(4, 4));
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(bad.string()), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_empty(dir));
  fs::remove_all(dir);
}

TEST(PngIo, RejectsMismatchedBuffer) {
  Image img{4, 4, std::vector<std::uint8_t>(10)};
  EXPECT_THROW(encode_png(img), std::invalid_argument);
}

TEST(PngIo, ReadMissingFileThrows) {
  EXPECT_THROW(read_png("/nonexistent/tumble.png"), std::runtime_error);
}

// A 720p frame goes through the reused per-thread scratch blocks (the
// second encode reuses the first's): same bytes both times, lossless.
// Encode speed is measured by `tumble bench --render`, not here.
TEST(PngIo, FrameSizedImagesRoundTripThroughReusedBuffers) {
  const fs::path dir = fresh_dir("png_720p");
  const Image img = frame_like(1280, 720);
  const std::vector<std::uint8_t> first = encode_png(img), second = encode_png(img);
  EXPECT_TRUE(first == second);
  write_png_atomic(dir / "f.png", img);
  EXPECT_TRUE(read_png(dir / "f.png").rgb == img.rgb);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tumble::io
