// Runs `tumble render` as a process the test can signal: spawn, wait for a
// frame, send SIGINT/SIGTERM/SIGKILL, inspect the folder.
#pragma once

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

extern char** environ;

namespace {

class RobustRender : public Cli {
 protected:
  static std::string data(const char* name) { return (kSource / "tests/app/data" / name).string(); }

  // Starts `tumble render SCENE -o DIR ...` without a shell, so a signal reaches
  // tumble itself. `path`, when given, replaces PATH (e.g. a fake ffmpeg first).
  pid_t spawn_render(const std::string& scene, const fs::path& out, std::vector<std::string> extra = {},
                     const std::string& path = "") const {
    const std::string bin = tumble_bin();
    std::vector<std::string> args = {bin, "render", scene, "-o", out.string()};
    if (std::find(extra.begin(), extra.end(), "--progress") == extra.end()) extra.insert(extra.end(), {"--progress", "none"});
    args.insert(args.end(), extra.begin(), extra.end());
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 1, (dir_ / "spawn.out").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&fa, 2, (dir_ / "spawn.err").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    std::vector<std::string> env;
    for (char** e = environ; *e; ++e)
      if (path.empty() || std::string(*e).rfind("PATH=", 0) != 0) env.emplace_back(*e);
    if (!path.empty()) env.push_back("PATH=" + path);
    std::vector<char*> envp;
    for (auto& e : env) envp.push_back(e.data());
    envp.push_back(nullptr);
    pid_t pid = -1;
    EXPECT_EQ(posix_spawn(&pid, bin.c_str(), &fa, nullptr, argv.data(), envp.data()), 0);
    posix_spawn_file_actions_destroy(&fa);
    return pid;
  }
  // Waits until frame `k` exists (the render is under way); false on timeout or early exit.
  static bool wait_for_frame(pid_t pid, const fs::path& out, int k) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06d.png", k);
    for (int i = 0; i < 60000; ++i) {
      if (fs::exists(out / name)) return true;
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
  // Every frame of `a` and `b` equal, byte for byte; both have `count` frames.
  void expect_same_frames(const fs::path& a, const fs::path& b, int count) const {
    for (int k = 0; k < count; ++k) {
      char name[32];
      std::snprintf(name, sizeof name, "frame_%06d.png", k);
      const std::string x = slurp(a / name), y = slurp(b / name);
      ASSERT_FALSE(x.empty()) << a / name;
      EXPECT_TRUE(x == y) << name << " differs";
    }
  }
};

}  // namespace
