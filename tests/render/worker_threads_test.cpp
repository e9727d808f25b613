// Worker threads follow the affinity mask and the cgroup quota, read from
// fake /proc/self/cgroup and cgroupfs trees (v2, v1, hybrid, nested).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "render/worker_threads.hpp"

namespace tumble::render {
namespace {
namespace fs = std::filesystem;

class FakeCgroup : public testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::path(testing::TempDir()) / ("tumble_cgroup_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(root_);
    fs::create_directories(root_ / "fs");
  }
  void TearDown() override { fs::remove_all(root_); }
  void write(const fs::path& rel, const std::string& text) {
    fs::create_directories((root_ / rel).parent_path());
    std::ofstream(root_ / rel) << text;
  }
  std::optional<double> limit() { return cgroup_cpu_limit(root_ / "self_cgroup", root_ / "fs"); }
  fs::path root_;
};

TEST_F(FakeCgroup, V2QuotaOfOwnGroup) {
  write("self_cgroup", "0::/job/task\n");
  write("fs/job/task/cpu.max", "150000 100000\n");
  ASSERT_TRUE(limit().has_value());
  EXPECT_DOUBLE_EQ(*limit(), 1.5);
}

TEST_F(FakeCgroup, V2MaxIsNoLimit) {
  write("self_cgroup", "0::/job\n");
  write("fs/job/cpu.max", "max 100000\n");
  EXPECT_FALSE(limit().has_value());
}

TEST_F(FakeCgroup, ParentQuotaCapsChild) {
  write("self_cgroup", "0::/a/b\n");
  write("fs/a/cpu.max", "200000 100000\n");
  write("fs/a/b/cpu.max", "max 100000\n");
  ASSERT_TRUE(limit().has_value());
  EXPECT_DOUBLE_EQ(*limit(), 2.0);
}

TEST_F(FakeCgroup, NamespacedPathFallsBackToMountRoot) {
  // In a container /proc/self/cgroup names a host path the mount lacks.
  write("self_cgroup", "0::/../host/slice\n");
  write("fs/cpu.max", "300000 100000\n");
  ASSERT_TRUE(limit().has_value());
  EXPECT_DOUBLE_EQ(*limit(), 3.0);
}

TEST_F(FakeCgroup, V1HybridCpuController) {
  write("self_cgroup", "4:memory:/x\n2:cpu,cpuacct:/docker/abc\n0::/\n");
  write("fs/cpu,cpuacct/docker/abc/cpu.cfs_quota_us", "50000\n");
  write("fs/cpu,cpuacct/docker/abc/cpu.cfs_period_us", "100000\n");
  ASSERT_TRUE(limit().has_value());
  EXPECT_DOUBLE_EQ(*limit(), 0.5);
}

TEST_F(FakeCgroup, V1MinusOneIsNoLimit) {
  write("self_cgroup", "1:cpu:/\n");
  write("fs/cpu/cpu.cfs_quota_us", "-1\n");
  write("fs/cpu/cpu.cfs_period_us", "100000\n");
  EXPECT_FALSE(limit().has_value());
}

TEST_F(FakeCgroup, MissingFilesAreNoLimit) {
  EXPECT_FALSE(limit().has_value());  // no /proc/self/cgroup at all
  write("self_cgroup", "0::/gone\n");
  EXPECT_FALSE(limit().has_value());
}

TEST(UsableCores, QuotaLowersAffinityRoundingUp) {
  EXPECT_EQ(usable_cores(16, std::nullopt), 16);
  EXPECT_EQ(usable_cores(16, 2.0), 2);
  EXPECT_EQ(usable_cores(16, 1.5), 2);
  EXPECT_EQ(usable_cores(16, 0.5), 1);
  EXPECT_EQ(usable_cores(2, 8.0), 2);  // a quota above the mask changes nothing
  EXPECT_EQ(usable_cores(0, std::nullopt), 1);
}

TEST(UsableCores, ThisProcessHasAtLeastOne) { EXPECT_GE(usable_cores(), 1); }

TEST(WorkerThreads, FlagThenEnvironmentThenMachine) {
  ::setenv("TUMBLE_JOBS", "3", 1);
  EXPECT_EQ(worker_threads(5), 5);
  EXPECT_EQ(worker_threads(), 3);
  ::setenv("TUMBLE_JOBS", "zero", 1);
  try {
    worker_threads();
    ADD_FAILURE() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("TUMBLE_JOBS"), std::string::npos) << e.what();
  }
  ::setenv("TUMBLE_JOBS", "0", 1);
  EXPECT_THROW(worker_threads(), std::invalid_argument);
  ::setenv("TUMBLE_JOBS", "4x", 1);
  EXPECT_THROW(worker_threads(), std::invalid_argument);
  ::unsetenv("TUMBLE_JOBS");
  EXPECT_EQ(worker_threads(), usable_cores());
}

}  // namespace
}  // namespace tumble::render
