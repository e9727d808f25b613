// Damaged copies of DejaVu Sans through the font check and, when it lets one
// through, stb_truetype (FontAtlas), built with AddressSanitizer + UBSan by
// scripts/font_mutations.sh: a stray read or a negative size aborts the run.
//   font_mutations ROUNDS SEED
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>

#include "render/font_atlas.hpp"
#include "render/resource_dir.hpp"

int main(int argc, char** argv) {
  std::ifstream in("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string font = ss.str();
  const int rounds = argc > 1 ? std::atoi(argv[1]) : 1000;
  std::mt19937_64 rnd(argc > 2 ? std::atoll(argv[2]) : 1);
  const std::string path = argc > 3 ? argv[3] : "/tmp/tumble_font_mutation.ttf";
  int loaded = 0;
  for (int r = 0; r < rounds; ++r) {
    std::string bad = font;
    const int mode = r % 4;  // the first tables; anywhere; loca and glyf heavily; cut anywhere
    if (mode == 3) bad.resize(rnd() % font.size());
    const std::size_t span = mode == 0 ? std::min<std::size_t>(bad.size(), 4096) : bad.size();
    const int bytes = mode == 3 ? 0 : 1 + static_cast<int>(rnd() % 32);
    for (int b = 0; b < bytes; ++b) bad[rnd() % span] = static_cast<char>(rnd());
    for (int b = 0; mode == 2 && b < 200; ++b) bad[bad.size() / 2 + rnd() % (bad.size() / 2)] = static_cast<char>(rnd());
    std::ofstream(path, std::ios::binary) << bad;
    try {
      const tumble::render::FontAtlas atlas(path);
      ++loaded;
    } catch (const tumble::render::ResourceError&) {
    }
  }
  std::printf("%d damaged fonts, %d let through and read whole, none read out of bounds\n", rounds, loaded);
}
