// Soak: a render of many frames, killed with SIGKILL at random
// points and resumed each time, ends byte-identical to a clean run with no
// temp file left. TUMBLE_SOAK_FRAMES sets the length (default 300, the CI
// size; 2000 locally: TUMBLE_SOAK_FRAMES=2000), TUMBLE_SOAK_SEED the kill times.
#include <cstdlib>
#include <iostream>
#include <random>

#include "render_fixture.hpp"

namespace {

class Soak : public RobustRender {};

long env_long(const char* name, long fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::atol(v) : fallback;
}

TEST_F(Soak, KilledAtRandomAndResumedEndsByteIdenticalToACleanRun) {
  TUMBLE_NEED_GL();
  const long frames = std::clamp(env_long("TUMBLE_SOAK_FRAMES", 300), 2L, 2000L);
  const std::string range = "0:" + std::to_string(frames - 1);
  const std::string scene = data("soak_render.toml");
  const fs::path out = dir_ / "soak", clean = dir_ / "clean";
  // The clean run first: the time to its first frame (set-up and simulation)
  // and its wall time scale the kill times, so a fast machine still gets
  // killed mid-run and a slow one still makes progress between kills.
  const auto c0 = std::chrono::steady_clock::now();
  auto ms_since = [](auto t) { return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count(); };
  const pid_t clean_pid = spawn_render(scene, clean, {"--frames", range});
  double first_ms = -1;
  int clean_st = 0;
  while (::waitpid(clean_pid, &clean_st, WNOHANG) != clean_pid) {
    if (first_ms < 0 && fs::exists(clean / "frame_000000.png")) first_ms = ms_since(c0);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ASSERT_TRUE(WIFEXITED(clean_st) && WEXITSTATUS(clean_st) == 0) << slurp(dir_ / "spawn.err");
  const double clean_ms = ms_since(c0);
  if (first_ms < 0) first_ms = clean_ms;
  std::mt19937 rng(static_cast<unsigned>(env_long("TUMBLE_SOAK_SEED", 13)));
  // Kill from half the set-up time to 15 % of the frame-writing time past it:
  // in the simulation, mid-frame, mid-rename, several times per run (with a
  // fixed 5-95 % of the whole run, 2000 frames took only 2 kills). After
  // kMaxKills the last run finishes.
  std::uniform_real_distribution<double> delay_ms(0.5 * first_ms, first_ms + 0.15 * (clean_ms - first_ms));
  const int kMaxKills = 25;
  int kills = 0, runs = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (bool done = false; !done; ++runs) {
    std::vector<std::string> extra = {"--frames", range};
    if (runs > 0) extra.push_back("--resume");
    const pid_t pid = spawn_render(scene, out, extra);
    const bool kill_this = kills < kMaxKills;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::microseconds(
                                                                  static_cast<long>(1000 * delay_ms(rng)));
    int st = 0;
    bool exited = false;
    while (!exited && (!kill_this || std::chrono::steady_clock::now() < deadline)) {
      exited = ::waitpid(pid, &st, WNOHANG) == pid;
      if (!exited) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    if (exited) {
      ASSERT_TRUE(WIFEXITED(st) && WEXITSTATUS(st) == 0) << slurp(dir_ / "spawn.err");
      done = true;
    } else {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &st, 0);
      ++kills;
    }
  }
  const double soak_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << "soak: " << frames << " frames, " << kills << " kill -9, " << runs << " runs, " << soak_s
            << " s (clean run " << clean_ms / 1000 << " s, first frame after " << first_ms / 1000 << " s)\n";
  EXPECT_GT(kills, 0) << "the render finished before the first kill: nothing was tested";
  EXPECT_EQ(names(out), names(clean));  // no stray temp files, no missing frames
  expect_same_frames(out, clean, static_cast<int>(frames));
  EXPECT_EQ(slurp(out / "manifest.json").find("\"complete\": false"), std::string::npos);
}

}  // namespace
