// The font checked before stb_truetype reads it: the real DejaVu Sans passes;
// truncated and corrupted copies are either refused by the check or read
// whole by stb_truetype without a crash (under ASan: without a stray read).
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>

#include "render/font_atlas.hpp"
#include "render/font_check.hpp"
#include "render/resource_dir.hpp"

namespace tumble::render {
namespace {

std::string font_bytes() {
  std::ifstream in(find_font_file(find_resource_dir()), std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// FontAtlas on `bytes` (written to a temp file): "" when it loads, else its message.
std::string load(const std::string& bytes) {
  const std::filesystem::path p = std::filesystem::path(testing::TempDir()) / "tumble_font_check.ttf";
  std::ofstream(p, std::ios::binary) << bytes;
  try {
    const FontAtlas atlas(p);
    return "";
  } catch (const ResourceError& e) {
    return e.what();
  }
}

TEST(FontCheck, TheRealFontPasses) {
  const std::string font = font_bytes();
  ASSERT_GT(font.size(), 100000u);
  EXPECT_EQ(truetype_problem(font), "");
}

TEST(FontCheck, TruncatedFontsAreRefusedWithWhereTheyEnd) {
  const std::string font = font_bytes();
  for (std::size_t n : {std::size_t(0), std::size_t(3), std::size_t(12), std::size_t(200), std::size_t(5000),
                        font.size() / 3, font.size() / 2, font.size() - 1}) {
    const std::string why = truetype_problem(font.substr(0, n));
    EXPECT_NE(why, "") << n << " bytes passed";
    const std::string msg = load(font.substr(0, n));
    EXPECT_NE(msg.find("damaged font"), std::string::npos) << n << ": " << msg;
    EXPECT_NE(msg.find("fonts-dejavu-core"), std::string::npos) << msg;
  }
}

// 400 copies with 1 to 64 bytes overwritten at random (a fixed seed): what the
// check lets through must load; before the check such copies crashed the render.
TEST(FontCheck, CorruptedFontsAreRefusedOrReadSafely) {
  const std::string font = font_bytes();
  std::mt19937_64 rnd(20261126);
  int refused = 0;
  for (int round = 0; round < 400; ++round) {
    std::string bad = font;
    const int bytes = 1 + static_cast<int>(rnd() % 64);
    // Half in the tables stb_truetype walks first (directory, head, hhea, maxp, cmap, loca), half anywhere.
    const std::size_t span = round % 2 ? bad.size() : std::min<std::size_t>(bad.size(), 4096);
    for (int b = 0; b < bytes; ++b) bad[rnd() % span] = static_cast<char>(rnd());
    const std::string msg = load(bad);
    refused += !msg.empty();
    if (!msg.empty()) {
      EXPECT_NE(msg.find("font"), std::string::npos) << msg;
    }
  }
  EXPECT_GT(refused, 0);
}

}  // namespace
}  // namespace tumble::render
