// Inputs that exist but are not readable regular files: a device,
// a directory, a FIFO, a file without read permission, as the scene file or a
// cloud file. Each fails at once with UnreadableFile (exit 1) saying what the
// path is; none hangs or reads without bound.
#include <linux/capability.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "expectations.hpp"

#include "base/input_file.hpp"
#include "scene/scene.hpp"

namespace fs = std::filesystem;
using tumble::UnreadableFile;
using tumble::scene::load_scene;

namespace {

const fs::path kDir = fs::path(TUMBLE_SOURCE_DIR) / "tests/scene/unreadable";

/// The message of the UnreadableFile that loading `p` throws ("" if none).
std::string unreadable_message(const fs::path& p) {
  try {
    load_scene(p);
  } catch (const UnreadableFile& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected UnreadableFile, got: " << e.what();
    return {};
  }
  ADD_FAILURE() << p << " loaded";
  return {};
}

TEST(UnreadableCorpus, EachFileReportsWhatItsCloudIs) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(kDir))
    if (e.path().extension() == ".toml") files.push_back(e.path());
  ASSERT_FALSE(files.empty()) << "no corpus in " << kDir;
  for (const fs::path& p : files) {
    SCOPED_TRACE(p.string());
    const auto expected = expectations(p);
    ASSERT_FALSE(expected.empty()) << "no '# expect:' line";
    const std::string msg = unreadable_message(p);
    EXPECT_EQ(msg.rfind(p.string() + ":", 0), 0u) << msg;
    for (const std::string& x : expected) EXPECT_NE(msg.find(x), std::string::npos) << "missing: " << x << "\ngot: " << msg;
  }
}

/// While alive, this thread's effective capabilities lack CAP_DAC_OVERRIDE and
/// CAP_DAC_READ_SEARCH, so mode 000 denies reading even to root (the tests run
/// as root in CI). The permitted set keeps them: the destructor restores them.
class WithoutDacOverride {
 public:
  WithoutDacOverride() {
    header_.version = _LINUX_CAPABILITY_VERSION_3;
    ok_ = ::syscall(SYS_capget, &header_, saved_) == 0;
    __user_cap_data_struct dropped[2] = {saved_[0], saved_[1]};
    dropped[0].effective &= ~((1u << CAP_DAC_OVERRIDE) | (1u << CAP_DAC_READ_SEARCH));
    ok_ = ok_ && ::syscall(SYS_capset, &header_, dropped) == 0;
  }
  ~WithoutDacOverride() { ::syscall(SYS_capset, &header_, saved_); }
  bool ok() const { return ok_; }

 private:
  __user_cap_header_struct header_{};
  __user_cap_data_struct saved_[2]{};
  bool ok_ = false;
};

class Unreadable : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("tumble_unreadable_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path scene_with_cloud(const std::string& cloud) const {
    const fs::path p = dir_ / "scene.toml";
    std::ofstream(p) << "[[bodies]]\ncloud = \"" << cloud << "\"\n";
    return p;
  }
  fs::path dir_;
};

TEST_F(Unreadable, FifoAsCloudOrSceneDoesNotWaitForAWriter) {
  ASSERT_EQ(::mkfifo((dir_ / "pipe").c_str(), 0644), 0);
  std::string msg = unreadable_message(scene_with_cloud("pipe"));
  EXPECT_NE(msg.find("scene.toml:2:9: error: bodies[0].cloud: "), std::string::npos) << msg;
  EXPECT_NE(msg.find("pipe: cloud file is a FIFO (named pipe), not a regular file"), std::string::npos) << msg;
  msg = unreadable_message(dir_ / "pipe");
  EXPECT_NE(msg.find("pipe: scene file is a FIFO (named pipe), not a regular file"), std::string::npos) << msg;
}

TEST_F(Unreadable, DeviceAndDirectoryAsSceneSayWhatTheyAre) {
  EXPECT_NE(unreadable_message("/dev/zero").find("/dev/zero: scene file is a character device"), std::string::npos);
  EXPECT_NE(unreadable_message(dir_).find("scene file is a directory"), std::string::npos);
}

TEST_F(Unreadable, PermissionDeniedEvenAsRoot) {
  std::ofstream(dir_ / "locked.xyz") << "1 0 0 1\n-1 0 0 1\n0 1 0 1\n0 0 1 1\n";
  std::ofstream(dir_ / "locked.toml") << "[[bodies]]\ncloud = \"locked.xyz\"\n";
  ::chmod((dir_ / "locked.xyz").c_str(), 0);
  const fs::path scene = scene_with_cloud("locked.xyz");
  ::chmod((dir_ / "locked.toml").c_str(), 0);
  const WithoutDacOverride no_bypass;
  ASSERT_TRUE(no_bypass.ok()) << "capset failed";
  std::string msg = unreadable_message(scene);
  EXPECT_NE(msg.find("scene.toml:2:9: error: bodies[0].cloud: "), std::string::npos) << msg;
  EXPECT_NE(msg.find("locked.xyz: cloud file cannot be read: permission denied"), std::string::npos) << msg;
  msg = unreadable_message(dir_ / "locked.toml");
  EXPECT_NE(msg.find("locked.toml: scene file cannot be read: permission denied"), std::string::npos) << msg;
}

TEST_F(Unreadable, OversizedFileIsRefusedBeforeReading) {
  // A sparse file: its size says 2 GiB, nothing is read or allocated.
  const fs::path big = dir_ / "big.xyz";
  std::ofstream(big).close();
  fs::resize_file(big, std::uintmax_t{2} << 30);
  try {
    tumble::read_input_file(big, 1 << 20, "cloud file");
    FAIL() << "read a file past the cap";
  } catch (const tumble::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("big.xyz: cloud file is 2147483648 bytes, more than the cap of 1048576 bytes"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
