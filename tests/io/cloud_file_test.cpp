// Plain-text clouds: `x y z m` per line, `#` comments, blank lines ignored;
// errors name source:line and say what was expected.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "base/error.hpp"
#include "io/cloud_file.hpp"

namespace tumble::io {
namespace {

TEST(CloudFile, ParsesNumbersCommentsAndBlankLines) {
  const std::string text =
      "# a header comment\n"
      "\n"
      "1 0 0 1.5   # trailing comment\n"
      "\t-1.0\t0\t0\t1.5\n"
      "   \n"
      "0 2.5e-1 -3E2 0.25\n"
      "0 0 1 2#no space before the hash\n";
  const ParticleCloud c = parse_cloud_text(text, "inline");
  ASSERT_EQ(c.size(), 4u);
  EXPECT_EQ(c[0].position, Eigen::Vector3d(1, 0, 0));
  EXPECT_EQ(c[0].mass, 1.5);
  EXPECT_EQ(c[1].position, Eigen::Vector3d(-1, 0, 0));
  EXPECT_EQ(c[2].position, Eigen::Vector3d(0, 0.25, -300));
  EXPECT_EQ(c[2].mass, 0.25);
  EXPECT_EQ(c[3].mass, 2.0);
  EXPECT_TRUE(parse_cloud_text("# only comments\n\n", "empty").empty());
}

void expect_error(const std::string& text, const std::string& where, const std::string& what) {
  try {
    parse_cloud_text(text, "parts.xyz");
    ADD_FAILURE() << "expected InputError for: " << text;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(where, 0), 0u) << msg << " should start with " << where;
    EXPECT_NE(msg.find(what), std::string::npos) << msg << " lacks " << what;
  }
}

TEST(CloudFile, ErrorsNameSourceAndLine) {
  expect_error("1 0 0 1\n# c\n1 2 3\n", "parts.xyz:3:", "expected 4 numbers");
  expect_error("1 0 0 1 5\n", "parts.xyz:1:", "found 5 fields");
  expect_error("\n1 0 zero 1\n", "parts.xyz:2:", "expected a number, found 'zero'");
  expect_error("1 0 0 1kg\n", "parts.xyz:1:", "found '1kg'");
  expect_error("1 0 0 1\nnan 0 0 1\n", "parts.xyz:2:", "finite");
  expect_error("1 0 0 inf\n", "parts.xyz:1:", "finite");
  expect_error("1 0 0 0\n", "parts.xyz:1:", "mass must be > 0");
  expect_error("1 0 0 -1\n", "parts.xyz:1:", "mass must be > 0");
}

TEST(CloudFile, ReadsFilesAndNamesThePath) {
  const auto dir = std::filesystem::temp_directory_path() / ("tumble_cloud_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto good = dir / "good.xyz", bad = dir / "bad.xyz";
  std::ofstream(good) << "# two particles\n1 0 0 1\n-1 0 0 1\n";
  std::ofstream(bad) << "1 0 0 1\n1 0 0\n";
  const ParticleCloud c = read_cloud_file(good);
  EXPECT_EQ(c.size(), 2u);
  try {
    read_cloud_file(bad);
    ADD_FAILURE() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(bad.string() + ":2:"), std::string::npos) << e.what();
  }
  try {
    read_cloud_file(dir / "missing.xyz");
    ADD_FAILURE() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.xyz"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

TEST(CloudFile, AppendCloudUnionsWithOffset) {
  ParticleCloud dst = {{{0, 0, 0}, 1.0}};
  append_cloud(dst, {{{1, 2, 3}, 2.0}, {{-1, 0, 0}, 0.5}}, {10, 0, -1});
  ASSERT_EQ(dst.size(), 3u);
  EXPECT_EQ(dst[1].position, Eigen::Vector3d(11, 2, 2));
  EXPECT_EQ(dst[2].position, Eigen::Vector3d(9, 0, -1));
  EXPECT_EQ(dst[2].mass, 0.5);
}

TEST(CloudFile, CsvWithHeaderInAnyColumnOrder) {
  const ParticleCloud c = parse_cloud_text("# scan\nm, z ,x,id,y\n2, 3, 1, 7, 0.5\n0.25,-1,4,8,5\n", "scan.csv");
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].position, Eigen::Vector3d(1, 0.5, 3));
  EXPECT_EQ(c[0].mass, 2.0);
  EXPECT_EQ(c[1].position, Eigen::Vector3d(4, 5, -1));
  EXPECT_EQ(c[1].mass, 0.25);
  // Header without commas, and CSV without a header.
  EXPECT_EQ(parse_cloud_text("X Y Z M\n1 2 3 4\n", "h.txt")[0].position, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(parse_cloud_text("1,2,3,4\n5,6,7,8\n", "n.csv")[1].mass, 8.0);
}

TEST(CloudFile, CsvErrorsNameTheLine) {
  expect_error("x,y,z\n1,2,3\n", "parts.xyz:1:", "no column named 'm'");
  expect_error("x,y,z,m,x\n1,2,3,4,5\n", "parts.xyz:1:", "appears twice");
  expect_error("x,y,z,m\n1,2,3,4\n1,2,3\n", "parts.xyz:3:", "expected 4");
  expect_error("x,y,z,m\n1,2,,4\n", "parts.xyz:2:", "expected a number, found ''");
}

TEST(CloudFile, CsvWithAUtf8ByteOrderMarkReadsItsHeader) {
  // Excel's "CSV UTF-8" export starts with EF BB BF (it said "no column named 'x'").
  const ParticleCloud c = parse_cloud_text("\xEF\xBB\xBFx,y,z,m\n1,2,3,4\n", "excel.csv");
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].mass, 4.0);
}

TEST(CloudFile, AHugeTokenIsQuotedShortInTheMessage) {
  try {
    (void)parse_cloud_text("1 2 3 " + std::string(1000000, '7') + "x\n", "big.xyz");
    FAIL() << "parsed";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_LT(m.size(), 200u) << m.substr(0, 300);
    EXPECT_NE(m.find("big.xyz:1: expected a number, found '" + std::string(80, '7') + "'... (1000001 bytes)"),
              std::string::npos) << m.substr(0, 300);
  }
}

}  // namespace
}  // namespace tumble::io
