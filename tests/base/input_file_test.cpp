// Inputs are remembered by identity so no output replaces them; an input that
// has since been removed must not be, because the kernel reuses its inode
// number for the next new file (the sanitized io tests met exactly this).
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "base/input_file.hpp"

namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("tumble_input_file_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

struct stat stat_of(const fs::path& p) {
  struct stat st {};
  EXPECT_EQ(::stat(p.c_str(), &st), 0) << p;
  return st;
}

}  // namespace

TEST(InputFile, AnInputStillAtItsPathIsKnownByIdentity) {
  const fs::path d = fresh_dir("known");
  std::ofstream(d / "a.txt") << "x";
  tumble::read_input_file(d / "a.txt", 16, "test file");
  const struct stat st = stat_of(d / "a.txt");
  const auto name = tumble::input_with_identity(st.st_dev, st.st_ino);
  ASSERT_TRUE(name.has_value());
  EXPECT_NE(name->find("a.txt"), std::string::npos) << *name;
  fs::remove_all(d);
}

TEST(InputFile, ARemovedInputNoLongerClaimsItsInodeNumber) {
  const fs::path d = fresh_dir("removed");
  std::ofstream(d / "a.txt") << "x";
  tumble::read_input_file(d / "a.txt", 16, "test file");
  const struct stat st = stat_of(d / "a.txt");
  fs::remove(d / "a.txt");
  // Whatever new file receives this inode number is not the input.
  EXPECT_FALSE(tumble::input_with_identity(st.st_dev, st.st_ino).has_value());
  fs::remove_all(d);
}

TEST(InputFile, AnInputReplacedAtItsPathIsNotTheNewFile) {
  const fs::path d = fresh_dir("replaced");
  std::ofstream(d / "a.txt") << "x";
  tumble::read_input_file(d / "a.txt", 16, "test file");
  const struct stat old = stat_of(d / "a.txt");
  std::ofstream(d / "b.txt") << "y";
  fs::rename(d / "b.txt", d / "a.txt");
  EXPECT_FALSE(tumble::input_with_identity(old.st_dev, old.st_ino).has_value());
  fs::remove_all(d);
}
