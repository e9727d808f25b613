// The atomic writer and its temp names.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "io/atomic_file.hpp"

namespace tumble::io {
namespace {
namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(testing::TempDir()) / ("tumble_io_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(AtomicFile, LeavesNothingWithoutCommit) {
  const fs::path dir = fresh_dir("nocommit");
  const fs::path p = dir / "a.txt";
  {
    AtomicFile f(p);
    f.write("partial");
    EXPECT_TRUE(fs::exists(temp_path_for(p)));  // the bytes go to the temp name first
  }
  EXPECT_TRUE(fs::is_empty(dir));
  atomic_write_file(p, "whole");
  EXPECT_EQ(slurp(p), "whole");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  atomic_write_file(p, "again", Durability::rename_only);
  EXPECT_EQ(slurp(p), "again");
  fs::remove_all(dir);
}

// A killed run leaves its temp file; this process's temp name may be the
// same (pids are reused), and the write goes on over it.
TEST(AtomicFile, ALeftoverTempFileOfTheSameNameIsReplaced) {
  const fs::path dir = fresh_dir("leftover");
  const fs::path p = dir / "a.txt";
  {
    std::ofstream(temp_path_for(p)) << "a killed run's half";
  }
  atomic_write_file(p, "whole");
  EXPECT_EQ(slurp(p), "whole");
  EXPECT_FALSE(fs::exists(temp_path_for(p)));
  fs::remove_all(dir);
}

TEST(AtomicFile, FailureNamesThePath) {
  const fs::path bad = fresh_dir("fail") / "missing" / "x.json";
  try {
    atomic_write_file(bad, "x");
    FAIL() << "expected IoError";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find(bad.string()), std::string::npos) << e.what();
  }
}

// The durability seam: at the moment of the fsync the temp file holds every
// byte written (the stdio buffer is flushed first), and the target does not
// yet have them (the rename comes after). Frames (rename_only) are not synced.
TEST(AtomicFile, SyncsTheWholeFileBeforeTheRename) {
  const fs::path dir = fresh_dir("sync");
  const fs::path p = dir / "m.json";
  atomic_write_file(p, "old");
  struct Seen {
    int count = 0;
    long size = -1;
    std::string target;
    fs::path tmp;
  } seen;
  test_hooks::set_sync_hook([&](int fd, const fs::path& tmp) {
    struct stat st {};
    ++seen.count;
    seen.size = ::fstat(fd, &st) == 0 ? static_cast<long>(st.st_size) : -1;
    seen.target = slurp(p);
    seen.tmp = tmp;
  });
  const std::string bytes(100, 'x');  // well inside one stdio buffer: only a flush puts it in the file
  atomic_write_file(p, bytes);
  const Seen fsynced = seen;
  seen = {};
  atomic_write_file(p, "frame", Durability::rename_only);
  test_hooks::set_sync_hook({});
  EXPECT_EQ(fsynced.count, 1);
  EXPECT_EQ(fsynced.size, 100) << "the bytes were not in the file when it was synced";
  EXPECT_EQ(fsynced.target, "old") << "the target changed before the sync";
  EXPECT_EQ(fsynced.tmp, temp_path_for(p));
  EXPECT_EQ(seen.count, 0) << "a rename_only write was synced";
  EXPECT_EQ(slurp(p), "frame");
  fs::remove_all(dir);
}

TEST(TempNames, TheTempNameOfAFileLeadsBackToIt) {
  const std::string tmp = temp_path_for("out/frame_000001.png").filename().string();
  EXPECT_EQ(tmp, "frame_000001.png.tmp-" + std::to_string(::getpid()));
  EXPECT_EQ(temp_target_name(tmp), "frame_000001.png");
  EXPECT_EQ(temp_target_name("manifest.json.tmp-99999"), "manifest.json");
}

TEST(TempNames, FinishedFilesAreNotTempFiles) {
  for (const char* name : {"manifest.json", "frame_000001.png", "a.tmp-", "a.tmp-12x", ".tmp-12", "notes.tmp-old",
                           "frame_000001.png.tmp.99999"})
    EXPECT_EQ(temp_target_name(name), "") << name;
}

}  // namespace
}  // namespace tumble::io
