// One writer per folder, shards of one render together: the admission is
// raced on purpose, many times, by processes released at the same instant.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/error.hpp"
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
/// (the parent closes its end), then each takes the folder as `mode` and holds
/// it for `hold_us`. Returns how many were refused.
int race(const fs::path& dir, FolderLock::Mode mode, const std::vector<std::string>& keys, int hold_us) {
  int gate[2];
  if (::pipe(gate) != 0) return -1;
  std::vector<pid_t> kids;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const pid_t pid = ::fork();
    if (pid == 0) {
      ::close(gate[1]);
      char c;
      (void)!::read(gate[0], &c, 1);  // returns 0 when the parent closes its end: go
      try {
        const FolderLock lock(dir, mode, "shard " + std::to_string(i), keys[i]);
        ::usleep(static_cast<useconds_t>(hold_us));
      } catch (const InputError&) {
        ::_exit(1);
      } catch (...) {
        ::_exit(2);
      }
      ::_exit(0);
    }
    kids.push_back(pid);
  }
  ::close(gate[0]);
  ::close(gate[1]);
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
  for (int round = 0; round < 300; ++round) refused += race(dir, FolderLock::Mode::shared, {"k", "k", "k", "k"}, 200);
  EXPECT_EQ(refused, 0) << "shards of one render refused each other " << refused << " times in 300 rounds of 4";
  fs::remove_all(dir);
}

// Two renders racing for one folder: whatever the timing, the shards of one
// are never let in beside the shards of the other, and one group gets it.
TEST(FolderLock, ShardsOfTwoRendersNeverShareAFolder) {
  const fs::path dir = fresh_dir("two");
  for (int round = 0; round < 100; ++round) {
    const int refused = race(dir, FolderLock::Mode::shared, {"a", "b", "a", "b"}, 20000);
    EXPECT_TRUE(refused == 2 || refused == 3) << "round " << round << ": " << refused << " of 4 refused";
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
