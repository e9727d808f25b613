// `tumble storyboard` end to end: the sheet holds, in reading order on a grid,
// exactly the frames `tumble render` writes (byte for byte, or scaled by
// io::resized), one for every flip and the spread over the video; bad options
// are refused before any work, naming the option; and `tumble render` warns of
// what the layout leaves out.
#include <algorithm>
#include <cmath>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"
#include "io/image_ops.hpp"
#include "io/json.hpp"
#include "io/png.hpp"

namespace {

using tumble::io::Image;

class StoryboardCli : public Cli {
 protected:
  // A box spun near its intermediate axis: it flips several times in 8 s; a
  // title card, slow motion at the first flip and a caption.
  std::string write_scene() const {
    const fs::path p = dir_ / "story.toml";
    std::ofstream(p) << "name = \"story\"\n[simulation]\nmethod = \"exact\"\nduration = 8\nfps = 10\n"
                        "[[bodies]]\nname = \"racket\"\n"
                        "shape = { type = \"box\", size = [0.3, 0.1, 0.02], resolution = 4, mass = 1 }\n"
                        "omega_body = [0.05, 5.0, 0.05]\n"
                        "[output]\nwidth = 160\nheight = 90\nvideo = \"none\"\n"
                        "[title]\ntext = \"t\"\nhold = 1.0\n"
                        "[[slow_motion]]\nstart = \"flip 1 - 0.2\"\nend = \"flip 1 + 0.2\"\ntime_scale = 0.25\n"
                        "[[captions]]\nstart = \"flip 2 - 0.5\"\nend = 8\ntext = \"the second flip\"\n";
    return "'" + p.string() + "'";
  }
  // The frames a storyboard's stdout lists.
  static std::vector<long> listed_frames(const std::string& out) {
    std::smatch m;
    EXPECT_TRUE(std::regex_search(out, m, std::regex(R"(\(frames ([0-9 ]+) of ([0-9]+)\))"))) << out;
    std::vector<long> v;
    std::istringstream in(m[1].str());
    for (long k; in >> k;) v.push_back(k);
    return v;
  }
  // Where `part` lies in `sheet` byte for byte, searched row-major; {-1, -1} when nowhere.
  static std::pair<int, int> locate(const Image& sheet, const Image& part) {
    const std::size_t row = static_cast<std::size_t>(part.width) * 3;
    for (int y = 0; y + part.height <= sheet.height; ++y)
      for (int x = 0; x + part.width <= sheet.width; ++x) {
        bool same = true;
        for (int r = 0; r < part.height && same; ++r) same = std::equal(part.pixel(0, r), part.pixel(0, r) + row, sheet.pixel(x, y + r));
        if (same) return {x, y};
      }
    return {-1, -1};
  }
  // Checks that the tiles of `frames` lie in `sheet` as `frame(k)` gives them, row-major on a grid of `columns`.
  template <class F>
  static void expect_tiles(const Image& sheet, const std::vector<long>& frames, int columns, F frame) {
    std::vector<std::pair<int, int>> at;
    for (long k : frames) {
      at.push_back(locate(sheet, frame(k)));
      EXPECT_GE(at.back().first, 0) << "frame " << k << " is not in the sheet as render draws it";
    }
    for (std::size_t i = 1; i < at.size(); ++i) {
      if (i % static_cast<std::size_t>(columns) == 0) {
        EXPECT_GT(at[i].second, at[i - 1].second) << "tile " << i << " starts a row";
        EXPECT_EQ(at[i].first, at[0].first) << "tile " << i;
      } else {
        EXPECT_EQ(at[i].second, at[i - 1].second) << "tile " << i;
        EXPECT_GT(at[i].first, at[i - 1].first) << "tile " << i;
      }
    }
  }
};

TEST_F(StoryboardCli, TilesAreRenderFramesAndEveryFlipAndTheSpreadAreThere) {
  TUMBLE_NEED_GL();
  const std::string scene = write_scene();
  const fs::path sheet_path = dir_ / "sheet.png";
  const Result r = run("storyboard " + scene + " -n 5 --columns 3 --tile-width 160 -o '" + sheet_path.string() +
                       "' --progress none");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::vector<long> frames = listed_frames(r.out);
  // Every flip at the first frame showing it (from `tumble info`'s flip times and frame times).
  const Result info = run("info " + scene + " --json");
  ASSERT_EQ(info.code, 0) << info.err;
  const auto j = tumble::io::Json::parse(info.out);
  const std::vector<double> times = j["frames"]["times"].get<std::vector<double>>();
  const long last = static_cast<long>(times.size()) - 1;
  const std::vector<double> flips = j["bodies"][0]["flip_times"].get<std::vector<double>>();
  ASSERT_GE(flips.size(), 2u);
  for (double f : flips) {
    const long k = std::find_if(times.begin(), times.end(), [&](double t) { return t >= f - 1e-9; }) - times.begin();
    EXPECT_NE(std::find(frames.begin(), frames.end(), k), frames.end()) << "no tile for the flip at t = " << f;
  }
  for (int i = 0; i < 5; ++i) {  // the spread of -n 5: first, last and three between, evenly
    const long s = std::lround(i * static_cast<double>(last) / 4);
    EXPECT_NE(std::find(frames.begin(), frames.end(), s), frames.end()) << "no tile for spread frame " << s;
  }
  EXPECT_TRUE(std::is_sorted(frames.begin(), frames.end()));
  EXPECT_EQ(std::adjacent_find(frames.begin(), frames.end()), frames.end()) << "a frame twice";
  // The sheet: 3 columns of 160 px tiles, as many rows as the tiles need, and tiles = render's frames.
  const Image sheet = tumble::io::read_png(sheet_path);
  const int rows = static_cast<int>((frames.size() + 2) / 3);
  EXPECT_GT(sheet.width, 3 * 160);
  EXPECT_LT(sheet.width, 3 * 160 + 4 * 30);
  EXPECT_GT(sheet.height, rows * (90 + 12));
  ASSERT_EQ(run("render " + scene + " -o '" + (dir_ / "full").string() + "' --progress none").code, 0);
  auto rendered = [&](long k) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06ld.png", k);
    return tumble::io::read_png(dir_ / "full" / name);
  };
  expect_tiles(sheet, frames, 3, rendered);
  // Scaled tiles: render's frames through io::resized, byte for byte.
  const Result half = run("storyboard " + scene + " -n 3 --columns 2 --tile-width 80 -o '" +
                          (dir_ / "half.png").string() + "' --progress none");
  ASSERT_EQ(half.code, 0) << half.err;
  expect_tiles(tumble::io::read_png(dir_ / "half.png"), listed_frames(half.out), 2,
               [&](long k) { return tumble::io::resized(rendered(k), 80, 45); });
  // Written atomically: nothing else is left beside the sheets.
  for (const auto& e : fs::directory_iterator(dir_))
    EXPECT_TRUE(e.path().extension() != ".png" || e.path().filename() == "sheet.png" || e.path().filename() == "half.png")
        << e.path();
}

TEST_F(StoryboardCli, BadOptionsAreRefusedNamingTheOptionAndWriteNothing) {
  const std::string scene = write_scene();
  const std::string out = " -o '" + (dir_ / "s.png").string() + "'";
  struct Case {
    std::string args, says;
    int code;
  };
  const std::vector<Case> cases = {
      {"-n -1" + out, "--frames", 2},
      {"-n 1000" + out, "--frames", 2},
      {"--tile-width 10" + out, "--tile-width", 2},
      {"--columns 0" + out, "--columns", 2},
      {"--columns 16 --width 1920 --height 1080 --tile-width 1920" + out, "--columns", 2},
      {"-o '" + (dir_ / "s.jpg").string() + "'", "ending in .png", 2},
      {"-o '" + (dir_ / "no" / "s.png").string() + "'", "does not exist", 1},
      {"--width 0" + out, "width", 2},
      {"--progress loud" + out, "--progress", 2},
  };
  for (const Case& c : cases) {
    const Result r = run("storyboard " + scene + " " + c.args);
    EXPECT_EQ(r.code, c.code) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << ": " << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "s.png")) << c.args;
  }
  fs::create_directories(dir_ / "d.png");
  const Result folder = run("storyboard " + scene + " -o '" + (dir_ / "d.png").string() + "'");
  EXPECT_EQ(folder.code, 2) << folder.err;
  EXPECT_NE(folder.err.find("found a folder"), std::string::npos) << folder.err;
}

// As render: a run that diverges shows the frames before, says so and exits 3.
TEST_F(StoryboardCli, ADivergingRunShowsTheFramesBeforeAndExits3) {
  TUMBLE_NEED_GL();
  const std::string scene = "'" + (kSource / "tests/app/data/damped_blowup_euler.toml").string() + "'";
  const Result r = run("storyboard " + scene + " -o '" + (dir_ / "d.png").string() + "' --progress none");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("diverged"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the storyboard shows frames 0-"), std::string::npos) << r.err;
  ASSERT_TRUE(fs::exists(dir_ / "d.png"));
  const std::vector<long> frames = listed_frames(r.out);
  ASSERT_FALSE(frames.empty());
  EXPECT_LT(frames.back(), 30) << "a frame past the divergence";
}

// What the layout leaves out is a warning of `tumble render` (and a line of
// `tumble info`): which element, which frames, why.
TEST_F(StoryboardCli, RenderWarnsOfWhatTheLayoutLeavesOut) {
  TUMBLE_NEED_GL();
  const std::string scene = "'" + (kSource / "tests/app/data/tiny_explained.toml").string() + "'";
  const Result r = run("render " + scene + " -o '" + (dir_ / "out").string() + "' --progress none");
  ASSERT_EQ(r.code, 0) << r.err;
  // 160 × 96: a key's text would be 2 px high; the title card holds frames 0-2.
  // (the world and body_frame views' keys repeat each other: one frame key for all)
  const std::string warning = "tumble: warning: frame key left out: its text would be 2 px high";
  EXPECT_NE(r.err.find(warning), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(frames 3-17)"), std::string::npos) << r.err;
  const Result info = run("info " + scene);
  ASSERT_EQ(info.code, 0) << info.err;
  EXPECT_NE(info.out.find("layout at 160x96"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("frame key left out"), std::string::npos) << info.out;
  const Result layout = run("render " + scene + " --layout '" + (dir_ / "l.jsonl").string() + "'");
  EXPECT_NE(layout.err.find(warning), std::string::npos) << layout.err;
}

}  // namespace
