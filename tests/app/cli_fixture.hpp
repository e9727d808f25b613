// Runs the built `tumble` binary as a user would: a temp folder per test,
// exit code, stdout and stderr captured.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace fs = std::filesystem;

namespace {

const fs::path kSource = TUMBLE_SOURCE_DIR;

/// The tumble under test: the build's, or TUMBLE_TEST_BIN (to run these tests
/// against another build, e.g. main's, to see which of them fail there).
inline std::string tumble_bin() {
  const char* e = std::getenv("TUMBLE_TEST_BIN");
  return e && *e ? e : TUMBLE_BIN;
}

/// Why no GL context can be made here ("" when one can). Asked of gl_probe,
/// which creates a context, never of the `tumble render` under test: a broken
/// render must fail its tests, not skip them. Probed once per process.
inline std::string gl_unavailable() {
#ifdef TUMBLE_GL_PROBE
  static const std::string why = [] {
    const fs::path err = fs::temp_directory_path() / ("tumble_gl_probe_" + std::to_string(::getpid()));
    const int st = std::system(("'" TUMBLE_GL_PROBE "' >/dev/null 2>'" + err.string() + "'").c_str());
    std::ifstream in(err);
    std::stringstream s;
    s << in.rdbuf();
    fs::remove(err);
    return WIFEXITED(st) && WEXITSTATUS(st) == 0 ? std::string() : "gl_probe: " + s.str();
  }();
  return why;
#else
  return "built without the renderer";
#endif
}

/// Skips a test that needs GL when there is none; with TUMBLE_REQUIRE_GL=1
/// (CI, which has GL) a missing context fails the test instead.
#define TUMBLE_NEED_GL()                                                                 \
  do {                                                                                   \
    const std::string why_no_gl = gl_unavailable();                                      \
    if (!why_no_gl.empty()) {                                                            \
      const char* req = std::getenv("TUMBLE_REQUIRE_GL");                                \
      if (req && std::string(req) == "1") FAIL() << "TUMBLE_REQUIRE_GL=1: " << why_no_gl; \
      GTEST_SKIP() << "no GL: " << why_no_gl;                                            \
    }                                                                                    \
  } while (0)

struct Result {
  int code;
  std::string out, err;
};

class Cli : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("tumble_cli_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
            std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  /// `tumble ARGS`, with `env` ("NAME=value ...") set and `wrapper` (a
  /// command such as setpriv ... --) in front.
  Result run(const std::string& args, const std::string& env = "", const std::string& wrapper = "") const {
    const fs::path out = dir_ / "stdout", err = dir_ / "stderr";
    const std::string cmd = (env.empty() ? "" : "env " + env + " ") + wrapper + (wrapper.empty() ? "" : " ") + "'" +
                            tumble_bin() + "' " + args + " >'" + out.string() + "' 2>'" + err.string() + "'";
    const int status = std::system(cmd.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out), slurp(err)};
  }
  // Runs tumble with at most `seconds` and 2 GB of address space: a hang or a
  // runaway read fails the test instead of the machine. Under AddressSanitizer
  // (whose shadow memory reserves terabytes of address space) only the time
  // limit applies. `prefix`: shell words before the command (ulimit -f 8; cd DIR &&).
  Result bounded(const std::string& args, int seconds = 20, const std::string& prefix = "") const {
    const fs::path out = dir_ / "stdout", err = dir_ / "stderr";
#if defined(__SANITIZE_ADDRESS__)
    const std::string limit = "";
#else
    const std::string limit = "ulimit -v 2000000; ";
#endif
    const std::string cmd = "bash -c \"" + limit + prefix + " exec timeout -s KILL " + std::to_string(seconds) + " '" +
                            tumble_bin() + "' " + args + "\" >'" + out.string() + "' 2>'" + err.string() + "'";
    const int st = std::system(cmd.c_str());
    return {WIFEXITED(st) ? WEXITSTATUS(st) : -1, slurp(out), slurp(err)};
  }
  static std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  static std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) out.push_back(l);
    return out;
  }
  static std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> out;
    std::istringstream in(line);
    for (std::string f; std::getline(in, f, ',');) out.push_back(f);
    return out;
  }
  std::string scene(const char* name) const { return "'" + (kSource / "scenes" / name).string() + "'"; }
  fs::path dir_;
};


}  // namespace
