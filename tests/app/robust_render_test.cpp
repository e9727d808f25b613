// Hardening of `tumble render` (issue 5): interrupted renders (SIGINT, SIGKILL)
// and --resume, output-folder safety (--force), write errors naming the path.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"
#include "io/frame_files.hpp"

extern char** environ;

namespace {

class RobustRender : public Cli {
 protected:
  static std::string data(const char* name) { return (kSource / "tests/app/data" / name).string(); }

  // Starts `tumble render SCENE -o DIR ...` without a shell, so a signal reaches tumble itself.
  pid_t spawn_render(const std::string& scene, const fs::path& out, std::vector<std::string> extra = {}) const {
    std::vector<std::string> args = {TUMBLE_BIN, "render", scene, "-o", out.string(), "--progress", "none"};
    args.insert(args.end(), extra.begin(), extra.end());
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 1, (dir_ / "spawn.out").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&fa, 2, (dir_ / "spawn.err").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t pid = -1;
    EXPECT_EQ(posix_spawn(&pid, TUMBLE_BIN, &fa, nullptr, argv.data(), environ), 0);
    posix_spawn_file_actions_destroy(&fa);
    return pid;
  }
  // Waits until frame `k` exists (the render is under way); false on timeout or early exit.
  static bool wait_for_frame(pid_t pid, const fs::path& out, int k) {
    for (int i = 0; i < 60000; ++i) {
      if (fs::exists(tumble::io::frame_path(out, k))) return true;
      int st;
      if (::waitpid(pid, &st, WNOHANG) == pid) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return false;
  }
  static int wait_exit(pid_t pid, int* signal = nullptr) {
    int st = 0;
    ::waitpid(pid, &st, 0);
    if (signal) *signal = WIFSIGNALED(st) ? WTERMSIG(st) : 0;
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  }
  // A whole PNG: signature first, IEND chunk last.
  static bool whole_png(const std::string& bytes) {
    static const std::string sig = "\x89PNG\r\n\x1a\n", iend = std::string("IEND\xae\x42\x60\x82", 8);
    return bytes.size() > 20 && bytes.compare(0, 8, sig) == 0 && bytes.compare(bytes.size() - 8, 8, iend) == 0;
  }
  std::vector<std::string> names(const fs::path& d) const {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(d)) out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
  }
  bool render_available() const {
    return run("render '" + data("tiny_render.toml") + "' -o '" + (dir_ / "probe").string() +
               "' --frames 0:0 --progress none").code == 0;
  }
  // Every frame of `a` and `b` equal, byte for byte; both have `count` frames.
  void expect_same_frames(const fs::path& a, const fs::path& b, int count) const {
    for (int k = 0; k < count; ++k) {
      const fs::path name = tumble::io::frame_path("", k);
      const std::string x = slurp(a / name), y = slurp(b / name);
      ASSERT_FALSE(x.empty()) << a / name;
      EXPECT_TRUE(x == y) << name << " differs";
    }
  }
};

constexpr int kSlowFrames = 161;  // slow_render.toml: 16 s at 10 fps

TEST_F(RobustRender, SigintKeepsWholeFramesAndAnIncompleteManifestThenResumeFinishes) {
  if (!render_available()) GTEST_SKIP() << "no GL backend";
  const fs::path out = dir_ / "int";
  const pid_t pid = spawn_render(data("slow_render.toml"), out);
  ASSERT_TRUE(wait_for_frame(pid, out, 3)) << slurp(dir_ / "spawn.err");
  ::kill(pid, SIGINT);
  ASSERT_EQ(wait_exit(pid), 130) << slurp(dir_ / "spawn.err");
  const std::string err = slurp(dir_ / "spawn.err");
  EXPECT_NE(err.find("interrupted (SIGINT)"), std::string::npos) << err;
  EXPECT_NE(err.find("--resume"), std::string::npos) << err;
  const std::string manifest = slurp(out / "manifest.json");
  EXPECT_NE(manifest.find("\"complete\": false"), std::string::npos) << manifest;
  int frames = 0;
  for (const std::string& n : names(out)) {
    EXPECT_EQ(n.find(".tmp"), std::string::npos) << n;
    if (n.rfind("frame_", 0) == 0) {
      ++frames;
      EXPECT_TRUE(whole_png(slurp(out / n))) << n;
    }
  }
  EXPECT_GE(frames, 4);
  EXPECT_LT(frames, kSlowFrames) << "the render finished before the signal; nothing was tested";
  EXPECT_NE(manifest.find("\"frames_written\": " + std::to_string(frames) + ","), std::string::npos) << manifest;

  const Result r = run("render '" + data("slow_render.toml") + "' -o '" + out.string() + "' --resume --progress none");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("already on disk"), std::string::npos) << r.out;
  EXPECT_NE(slurp(out / "manifest.json").find("\"complete\": true"), std::string::npos);
}

TEST_F(RobustRender, SigtermExits143) {
  if (!render_available()) GTEST_SKIP() << "no GL backend";
  const fs::path out = dir_ / "term";
  const pid_t pid = spawn_render(data("slow_render.toml"), out);
  ASSERT_TRUE(wait_for_frame(pid, out, 2)) << slurp(dir_ / "spawn.err");
  ::kill(pid, SIGTERM);
  EXPECT_EQ(wait_exit(pid), 143) << slurp(dir_ / "spawn.err");
  EXPECT_NE(slurp(out / "manifest.json").find("\"complete\": false"), std::string::npos);
}

TEST_F(RobustRender, KilledRenderResumesByteIdenticalToACleanRun) {
  if (!render_available()) GTEST_SKIP() << "no GL backend";
  const fs::path out = dir_ / "killed", clean = dir_ / "clean";
  const pid_t pid = spawn_render(data("slow_render.toml"), out);
  ASSERT_TRUE(wait_for_frame(pid, out, 5)) << slurp(dir_ / "spawn.err");
  ::kill(pid, SIGKILL);
  int sig = 0;
  wait_exit(pid, &sig);
  ASSERT_EQ(sig, SIGKILL);
  // What a kill -9 in the middle of a write leaves: a temp file. Resume removes it.
  std::ofstream(out / "frame_000150.png.tmp-99999") << "partial";
  std::ofstream(out / "manifest.json.tmp-99999") << "{";
  for (const std::string& n : names(out))
    if (n.rfind("frame_", 0) == 0 && n.find(".tmp") == std::string::npos) {
      EXPECT_TRUE(whole_png(slurp(out / n))) << n;
    }

  const Result r = run("render '" + data("slow_render.toml") + "' -o '" + out.string() + "' --resume --progress none");
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_EQ(run("render '" + data("slow_render.toml") + "' -o '" + clean.string() + "' --progress none").code, 0);
  EXPECT_EQ(names(out), names(clean));
  expect_same_frames(out, clean, kSlowFrames);
}

TEST_F(RobustRender, RefusesAnotherScenesRenderUnlessForced) {
  if (!render_available()) GTEST_SKIP() << "no GL backend";
  const std::string out = (dir_ / "o").string();
  ASSERT_EQ(run("render '" + data("slow_render.toml") + "' -o '" + out + "' --progress none --frames 0:20").code, 0);
  Result r = run("render '" + data("tiny_render.toml") + "' -o '" + out + "' --progress none");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("holds a render of another scene"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--force"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "o" / "frame_000020.png"));  // nothing touched

  // Same scene, other settings: refused too (its frames would pass for ours on --resume).
  r = run("render '" + data("slow_render.toml") + "' -o '" + out + "' --progress none --width 64 --frames 0:0");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("other settings"), std::string::npos) << r.err;

  // --force replaces it: the 21 old frames go, stale ones beyond the new 7 included.
  r = run("render '" + data("tiny_render.toml") + "' -o '" + out + "' --progress none --force");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "o" / "frame_000006.png"));
  EXPECT_FALSE(fs::exists(dir_ / "o" / "frame_000007.png"));
  EXPECT_FALSE(fs::exists(dir_ / "o" / "frame_000020.png"));
}

TEST_F(RobustRender, RefusesAFolderOfFramesWithoutManifest) {
  fs::create_directories(dir_ / "foreign");
  std::ofstream(dir_ / "foreign" / "frame_000000.png") << "not ours";
  const Result r = run("render '" + data("tiny_render.toml") + "' -o '" + (dir_ / "foreign").string() + "' --progress none");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("no manifest.json"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(dir_ / "foreign" / "frame_000000.png"), "not ours");
}

TEST_F(RobustRender, CreatesMissingOutputFolders) {
  if (!render_available()) GTEST_SKIP() << "no GL backend";
  const Result r = run("render '" + data("tiny_render.toml") + "' -o '" + (dir_ / "a/b/c").string() + "' --progress none --frames 0:0");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "a/b/c/frame_000000.png"));
}

TEST_F(RobustRender, UncreatableOutputFolderNamesThePathAndExits1) {
  std::ofstream(dir_ / "file") << "x";
  const Result r = run("render '" + data("tiny_render.toml") + "' -o '" + (dir_ / "file/sub").string() + "' --progress none");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find((dir_ / "file/sub").string()), std::string::npos) << r.err;
}

TEST_F(RobustRender, FullDiskNamesTheFrameAndExits1) {
  if (!render_available()) GTEST_SKIP() << "no GL backend";
  // RLIMIT_FSIZE with SIGXFSZ ignored: writes past 4 KiB fail with EFBIG, like a full disk.
  const fs::path out = dir_ / "full";
  const std::string cmd = "ulimit -f 4; trap '' XFSZ; '" + std::string(TUMBLE_BIN) + "' render '" +
                          data("slow_render.toml") + "' -o '" + out.string() + "' --progress none >'" +
                          (dir_ / "o").string() + "' 2>'" + (dir_ / "e").string() + "'";
  const int st = std::system(("bash -c \"" + cmd + "\"").c_str());
  ASSERT_TRUE(WIFEXITED(st));
  EXPECT_EQ(WEXITSTATUS(st), 1) << slurp(dir_ / "e");
  const std::string err = slurp(dir_ / "e");
  EXPECT_NE(err.find(out.string() + "/frame_"), std::string::npos) << err;
  EXPECT_EQ(err.find("internal error"), std::string::npos) << err;
  for (const std::string& n : names(out)) EXPECT_EQ(n.find(".tmp"), std::string::npos) << n;
}

TEST_F(RobustRender, SceneNameCannotLeaveTheOutputFolder) {
  std::ofstream(dir_ / "evil.toml") << "name = \"../../escape\"\n[[bodies]]\n"
                                       "particles = [[1, 0, 0, 1], [-1, 0, 0, 1], [0, 1, 0, 0.5], [0, -1, 0, 0.5]]\n";
  const Result r = run("render '" + (dir_ / "evil.toml").string() + "' --progress none");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("evil.toml:1:8: error: name: expected 1-64 characters"), std::string::npos) << r.err;
}

}  // namespace
