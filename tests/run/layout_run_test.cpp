// run::write_layout_report (`tumble render --layout`): the asked frames, every
// item once per frame, the file written whole; a bad range is refused before work.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "base/error.hpp"
#include "io/json.hpp"
#include "run/layout_run.hpp"
#include "scene/scene.hpp"

namespace {

namespace fs = std::filesystem;

TEST(LayoutRun, WritesTheAskedFramesAndSaysWhich) {
  const tumble::scene::Scene s =
      tumble::scene::load_scene(fs::path(TUMBLE_SOURCE_DIR) / "scenes/poinsot.toml");
  const fs::path file = fs::temp_directory_path() / ("tumble_layout_run_" + std::to_string(::getpid()) + ".jsonl");
  const tumble::run::LayoutSummary r = tumble::run::write_layout_report(s, "200:201", file);  // past the title card
  EXPECT_EQ(r.first, 200);
  EXPECT_EQ(r.last, 201);
  // The whole video: 6 s title + 8.5 s at ×1/4 + holds 6+6+6.5+4+3.5+3+4.5+9 s = 82.5 s at 30 fps, and its last frame.
  EXPECT_EQ(r.count, 2476);
  EXPECT_EQ(r.width, s.render.output.width);
  EXPECT_EQ(r.height, s.render.output.height);
  std::ifstream in(file);
  std::set<long> frames;
  long lines = 0;
  for (std::string line; std::getline(in, line); ++lines)
    frames.insert(tumble::io::Json::parse(line).at("frame").get<long>());
  EXPECT_EQ(frames, (std::set<long>{200, 201}));
  EXPECT_GT(lines, 4);  // Π, L, ω, titles... per frame
  fs::remove(file);
  EXPECT_THROW(tumble::run::write_layout_report(s, "9:99999", file), tumble::InputError);
  EXPECT_FALSE(fs::exists(file));
}

}  // namespace
