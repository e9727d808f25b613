// The names of a render's shard manifests and the gaps between shards
// (run/manifest_parts.hpp), which `tumble assemble` reports.
#include <gtest/gtest.h>

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

}  // namespace
