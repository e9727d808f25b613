#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "io/json.hpp"

namespace tumble::io {
namespace {
namespace fs = std::filesystem;

TEST(Json, KeepsKeyOrderAndRoundTripsThroughAFile) {
  const fs::path p = fs::path(testing::TempDir()) / ("tumble_json_" + std::to_string(::getpid()) + ".json");
  Json j;
  j["tool"] = "tumble";
  j["dt"] = 0.1;
  j["frames"] = {3, 9};
  j["complete"] = true;
  j["odd \"name\"\\"] = "tab\there";
  write_json_atomic(p, j);
  const std::optional<Json> back = read_json_file(p);
  ASSERT_TRUE(back);
  EXPECT_EQ(*back, j);
  EXPECT_EQ(back->begin().key(), "tool");
  EXPECT_EQ((*back)["dt"].get<double>(), 0.1);  // doubles read back exactly
  EXPECT_NE(json_text(j).find("\"complete\": true,\n"), std::string::npos) << json_text(j);
  fs::remove(p);
}

TEST(Json, BytesThatAreNotUtf8DoNotThrow) {
  Json j;
  j["path"] = std::string("caf\xe9.toml");
  EXPECT_NE(json_text(j).find("caf\xef\xbf\xbd.toml"), std::string::npos);
}

TEST(Json, MissingOrBrokenFilesReadAsNothing) {
  const fs::path p = fs::path(testing::TempDir()) / ("tumble_json_bad_" + std::to_string(::getpid()) + ".json");
  EXPECT_FALSE(read_json_file(p));
  std::ofstream(p) << "{\"tool\": ";
  EXPECT_FALSE(read_json_file(p));
  fs::remove(p);
}

}  // namespace
}  // namespace tumble::io
