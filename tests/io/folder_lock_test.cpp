// One writer per folder, shards of one render together: the admission is
// raced on purpose, many times, by processes released at the same instant.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "io/folder_lock.hpp"

namespace tumble::io {
namespace {
namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(testing::TempDir()) / ("tumble_lock_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// Forks one process per key; all wait on one pipe and are let go together
/// (the parent closes its end), then each tries to take the folder as `mode`
/// and reports that it has tried. A process that got in holds the folder
/// until every process has tried (the parent closes a second pipe), so no
/// holder leaves before a later one arrives, however the scheduler orders
/// them: the outcome depends on the lock alone, never on timing.
/// Returns how many were refused.
int race(const fs::path& dir, FolderLock::Mode mode, const std::vector<std::string>& keys) {
  int gate[2], tried[2], release[2];
  if (::pipe(gate) != 0 || ::pipe(tried) != 0 || ::pipe(release) != 0) return -1;
  std::vector<pid_t> kids;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const pid_t pid = ::fork();
    if (pid == 0) {
      ::close(gate[1]);
      ::close(tried[0]);
      ::close(release[1]);
      char c = 0;
      (void)!::read(gate[0], &c, 1);  // returns 0 when the parent closes its end: go
      int code = 0;
      try {
        const FolderLock lock(dir, mode, "shard " + std::to_string(i), keys[i]);
        (void)!::write(tried[1], "y", 1);
        (void)!::read(release[0], &c, 1);  // hold until everyone has tried
      } catch (const InputError&) {
        code = 1;
      } catch (...) {
        code = 2;
      }
      if (code != 0) (void)!::write(tried[1], "n", 1);
      ::_exit(code);
    }
    kids.push_back(pid);
  }
  ::close(gate[0]);
  ::close(tried[1]);
  ::close(release[0]);
  ::close(gate[1]);  // go
  char c = 0;
  for (std::size_t i = 0; i < keys.size() && ::read(tried[0], &c, 1) == 1; ++i) {
  }
  ::close(tried[0]);
  ::close(release[1]);  // every process has tried: the holders may go
  int refused = 0;
  for (pid_t pid : kids) {
    int st = 0;
    ::waitpid(pid, &st, 0);
    refused += !(WIFEXITED(st) && WEXITSTATUS(st) == 0);
  }
  return refused;
}

// Each shard that finds the lock free takes it exclusively for a moment (to
// write its note) before sharing it; another shard arriving in that moment
// must wait for the decision, not be refused. 300 rounds of 4 shards.
TEST(FolderLock, ShardsStartingTogetherNeverRefuseEachOther) {
  const fs::path dir = fresh_dir("shards");
  int refused = 0;
  for (int round = 0; round < 300; ++round) refused += race(dir, FolderLock::Mode::shared, {"k", "k", "k", "k"});
  EXPECT_EQ(refused, 0) << "shards of one render refused each other " << refused << " times in 300 rounds of 4";
  fs::remove_all(dir);
}

// Two renders racing for one folder: whatever the order, the shards of one
// are never let in beside the shards of the other, and one group gets it
// whole (both its shards: each arrives while its sibling holds the folder).
TEST(FolderLock, ShardsOfTwoRendersNeverShareAFolder) {
  const fs::path dir = fresh_dir("two");
  for (int round = 0; round < 100; ++round) {
    const int refused = race(dir, FolderLock::Mode::shared, {"a", "b", "a", "b"});
    EXPECT_EQ(refused, 2) << "round " << round << ": " << refused << " of 4 refused";
  }
  fs::remove_all(dir);
}

TEST(FolderLock, AnExclusiveHolderRefusesShardsAndIsNamed) {
  const fs::path dir = fresh_dir("exclusive");
  const FolderLock held(dir, FolderLock::Mode::exclusive, "tumble render a.toml", "a");
  try {
    const FolderLock shard(dir, FolderLock::Mode::shared, "tumble render a.toml --frames 0:1", "a");
    ADD_FAILURE() << "a shard was let in beside an exclusive holder";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is in use by pid " + std::to_string(::getpid()) + ", tumble render a.toml"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(FolderLock::refuse_if_held(dir, "a"), InputError);  // exclusive: not siblings
}

TEST(FolderLock, RefuseIfHeldLetsASiblingShardOn) {
  const fs::path dir = fresh_dir("siblings");
  EXPECT_EQ(FolderLock::refuse_if_held(dir, "k"), FolderLock::Holder::none);
  const FolderLock shard(dir, FolderLock::Mode::shared, "tumble render a.toml --frames 0:1", "k");
  EXPECT_EQ(FolderLock::refuse_if_held(dir, "k"), FolderLock::Holder::siblings);
  EXPECT_THROW(FolderLock::refuse_if_held(dir, "other"), InputError);
  EXPECT_THROW(FolderLock::refuse_if_held(dir), InputError);  // not a shard: in use
}

}  // namespace
}  // namespace tumble::io
