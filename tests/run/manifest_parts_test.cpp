// The names of a render's shard manifests and the gaps between shards
// (run/manifest_parts.hpp), which `tumble assemble` reports.
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "base/error.hpp"
#include "run/assemble.hpp"
#include "run/manifest_parts.hpp"

namespace {

using tumble::run::is_part_manifest;
using tumble::run::missing_ranges;
using tumble::run::part_manifest_name;

TEST(ManifestParts, NamesSortByFrameAndReadBack) {
  EXPECT_EQ(part_manifest_name(120, 239), "manifest.part-000120-000239.json");
  EXPECT_TRUE(is_part_manifest(part_manifest_name(0, 6)));
  EXPECT_FALSE(is_part_manifest("manifest.part-1-2.json"));
  EXPECT_FALSE(is_part_manifest("manifest.json"));
  EXPECT_FALSE(is_part_manifest("manifest.part-000000-000006.json.tmp-12"));
}

TEST(ManifestParts, MissingRangesNameEveryGap) {
  EXPECT_EQ(missing_ranges({{0, 1}, {4, 6}}, 10), "2:3, 7:9");
  EXPECT_EQ(missing_ranges({{3, 9}, {0, 5}}, 10), "");  // overlapping, unsorted
  EXPECT_EQ(missing_ranges({}, 7), "0:6");
  EXPECT_EQ(missing_ranges({{0, 0}, {2, 2}}, 3), "1:1");
  EXPECT_EQ(missing_ranges({{1, 12}}, 5), "0:0");  // a range past the end covers no more
}

// A part whose numbers were changed on disk (an absurd or negative
// frame_count, a range outside it) is not a part; assemble names it instead of
// sizing a table by it ("internal error: std::bad_alloc" before).
TEST(ManifestParts, APartWithAbsurdNumbersIsNotOk) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("tumble_parts_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path part = dir / part_manifest_name(0, 3);
  auto write = [&](const std::string& count, const std::string& range, const std::string& written) {
    std::ofstream(part, std::ios::trunc) << R"({"tool": "tumble", "scene_hash": "a", "settings_hash": "b", "fps": 10, )"
                                         << R"("width": 96, "height": 72, "frames": )"
                                         << range << R"(, "frame_count": )" << count << R"(, "frames_written": )"
                                         << written << R"(, "complete": true})";
    return tumble::run::read_part(part).ok;
  };
  EXPECT_TRUE(write("7", "[0, 3]", "4"));
  EXPECT_FALSE(write("4000000000000000000", "[0, 3]", "4"));
  EXPECT_FALSE(write("-5", "[0, 3]", "4"));
  EXPECT_FALSE(write("3", "[0, 3]", "4"));   // range past the end
  EXPECT_FALSE(write("7", "[3, 0]", "4"));   // backwards
  EXPECT_FALSE(write("7", "[0, 3]", "-1"));
  EXPECT_FALSE(write("7", "[0, 3]", "5"));   // more written than the range holds
  // The video's CRF is checked as the scene checks it: 0..51, the ends included.
  auto crf = [&](const std::string& c) {
    std::ofstream(part, std::ios::trunc) << R"({"tool": "tumble", "scene_hash": "a", "settings_hash": "b", "fps": 10, )"
                                         << R"("width": 96, "height": 72, "frames": [0, 3], "frame_count": 7, )"
                                         << R"("frames_written": 4, "complete": true, "video_format": "mp4", "crf": )" << c << "}";
    return tumble::run::read_part(part).ok;
  };
  EXPECT_TRUE(crf("0"));
  EXPECT_TRUE(crf("51"));
  EXPECT_FALSE(crf("52"));
  EXPECT_FALSE(crf("-1"));
  write("4000000000000000000", "[0, 3]", "4");
  struct Quiet : tumble::run::Listener {
    void note(const std::string&) override {}
    void begin(long, const std::string&) override {}
    void advance(long) override {}
    void end() override {}
    void arm_stop() override {}
    int stop() const override { return 0; }
  } l;
  try {
    tumble::run::assemble(dir, std::nullopt, l);
    ADD_FAILURE() << "assembled a part of 4e18 frames";
  } catch (const tumble::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no manifest part in " + dir.string() + " was written by tumble"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

}  // namespace
