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

// A read that would run past the end is refused before it reads, naming the
// first byte it would need: 3 bytes hold no 4-byte version tag.
TEST(FontCheck, AReadRunningPastTheEndIsRefusedBeforeItReads) {
  const std::string font = font_bytes();
  EXPECT_NE(truetype_problem(font.substr(0, 3)).find("cut short (reads byte 4 of a span ending at 3)"), std::string::npos)
      << truetype_problem(font.substr(0, 3));
}

// 400 damaged copies (a fixed seed): 1 to 32 bytes overwritten in the tables
// stb_truetype walks first, or anywhere; the second half of the file (loca,
// glyf) overwritten 200 times; or cut anywhere. What the check lets through
// must load, and under the sanitizers (ctest --preset asan) without a stray
// read: 24 000 such copies ran clean there (a reversed glyph box was the
// last hole: a negative bitmap width). Before the check such copies crashed.
TEST(FontCheck, DamagedFontsAreRefusedOrReadSafely) {
  const std::string font = font_bytes();
  std::mt19937_64 rnd(20261126);
  int refused = 0;
  for (int round = 0; round < 400; ++round) {
    std::string bad = font;
    const int mode = round % 4;
    if (mode == 3) bad.resize(rnd() % font.size());
    const std::size_t span = mode == 0 ? std::min<std::size_t>(bad.size(), 4096) : bad.size();
    const int bytes = mode == 3 ? 0 : 1 + static_cast<int>(rnd() % 32);
    for (int b = 0; b < bytes; ++b) bad[rnd() % span] = static_cast<char>(rnd());
    for (int b = 0; mode == 2 && b < 200; ++b) bad[bad.size() / 2 + rnd() % (bad.size() / 2)] = static_cast<char>(rnd());
    const std::string msg = load(bad);
    refused += !msg.empty();
    if (!msg.empty()) {
      EXPECT_NE(msg.find("font"), std::string::npos) << msg;
    }
  }
  EXPECT_GT(refused, 100);
}

TEST(FontCheck, AReversedGlyphBoxIsRefused) {
  std::string font = font_bytes();
  // The first glyph with an outline: its xMin (offset 2) set above its xMax.
  const auto u16 = [&](std::size_t at) { return (static_cast<unsigned char>(font[at]) << 8) | static_cast<unsigned char>(font[at + 1]); };
  const auto u32 = [&](std::size_t at) { return (std::size_t(u16(at)) << 16) | u16(at + 2); };
  std::size_t glyf = 0, loca = 0;
  for (std::size_t i = 0, n = u16(4); i < n; ++i) {
    const std::string tag = font.substr(12 + 16 * i, 4);
    if (tag == "glyf") glyf = u32(12 + 16 * i + 8);
    if (tag == "loca") loca = u32(12 + 16 * i + 8);
  }
  ASSERT_GT(glyf, 0u);
  std::size_t g = 0;
  for (std::size_t k = 0; g == 0; ++k)  // DejaVu's loca is long (4 bytes an entry)
    if (u32(loca + 4 * k + 4) > u32(loca + 4 * k)) g = glyf + u32(loca + 4 * k);
  font[g + 2] = 0x7f;
  EXPECT_NE(truetype_problem(font).find("reversed bounding box"), std::string::npos) << truetype_problem(font);
}

}  // namespace
}  // namespace tumble::render
