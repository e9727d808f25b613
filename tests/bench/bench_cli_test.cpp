// `tumble bench --scene FILE` and the dispatch of `tumble bench` to
// tumble-bench, run as a user would (the built binary, exit codes, files written).
#include <set>

#include "../app/cli_fixture.hpp"

namespace {

// Two bodies: one torque-free (closed-form reference, peers run) and one
// pushed off-centre (dop853 reference, odeint's body-frame peers only). Short, so --quick stays quick.
constexpr const char* kScene = R"(name = "bench_pair"
[simulation]
method = "splitting"
dt = 1e-3
duration = 2.0
fps = 30

[[bodies]]
name = "free"
particles = [[1.0, 0.0, 0.0, 1.0], [-1.0, 0.0, 0.0, 1.0], [0.0, 1.0, 0.0, 0.5], [0.0, -1.0, 0.0, 0.5]]
omega_body = [0.01, 10.0, 0.01]

[[bodies]]
name = "pushed"
shape = { type = "box", size = [0.6, 0.3, 0.15], resolution = [4, 2, 2], mass = 2.0 }
omega_body = [0.3, 1.5, 0.1]

[[bodies.forces]]
force = [0.0, 0.12, 0.0]
point = [0.3, 0.0, 0.0]
frame = "body"
)";

class BenchCli : public Cli {
 protected:
  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p;
  }
  static bool gnuplot() { return std::system("gnuplot --version > /dev/null 2>&1") == 0; }
};

TEST_F(BenchCli, SceneStudyWritesCsvChartsAndSummary) {
  const fs::path scene = write("pair.toml", kScene), out = dir_ / "out";
  const Result r = run("bench --quick --scene '" + scene.string() + "' -o '" + out.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* f : {"work_precision.csv", "convergence_orders.csv", "cheapest.csv", "summary.md"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  if (gnuplot()) {
    for (const char* f : {"work_precision_free.png", "work_precision_pushed.png", "convergence_free.png"})
      EXPECT_TRUE(fs::exists(out / f)) << f;
  }
  std::set<std::string> seen;  // "body method"
  const auto rows = lines(slurp(out / "work_precision.csv"));
  ASSERT_GT(rows.size(), 1u);
  EXPECT_EQ(rows[0], "problem,method,param_name,param,cpu_s,angle_err_rad,energy_rel_err");
  for (size_t i = 1; i < rows.size(); ++i) {
    const auto f = split(rows[i]);
    ASSERT_EQ(f.size(), 7u) << rows[i];
    seen.insert(f[0] + " " + f[1]);
  }
  for (const char* m : {"euler", "rk4", "rk45", "splitting", "splitting4", "exact"}) {
    EXPECT_TRUE(seen.count(std::string("free ") + m)) << m;
    EXPECT_TRUE(seen.count(std::string("pushed ") + m)) << m;
  }
  // odeint's body-frame peers take forces (core's right-hand side); the world-frame one and the engines do not.
  EXPECT_TRUE(seen.count("free odeint_rk4_body"));
  EXPECT_TRUE(seen.count("pushed odeint_rk4_body"));
  EXPECT_TRUE(seen.count("pushed odeint_dopri5_body"));
  EXPECT_FALSE(seen.count("pushed odeint_rk4_world"));
  const std::string md = slurp(out / "summary.md");
  EXPECT_NE(md.find("bench_pair"), std::string::npos);
  EXPECT_NE(md.find("**cheapest**"), std::string::npos);
}

TEST_F(BenchCli, SceneStudyOfOneBody) {
  const fs::path scene = write("pair.toml", kScene), out = dir_ / "out";
  const Result r = run("bench --quick --scene '" + scene.string() + "' --body pushed -o '" + out.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string csv = slurp(out / "work_precision.csv");
  EXPECT_NE(csv.find("\npushed,"), std::string::npos);
  EXPECT_EQ(csv.find("\nfree,"), std::string::npos);
}

TEST_F(BenchCli, BadSceneExits2WithItsLocation) {
  const fs::path scene = write("bad.toml", "name = \"x\"\n[simulation]\nmethod = \"rk5\"\n");
  const Result r = run("bench --quick --scene '" + scene.string() + "' -o '" + (dir_ / "out").string() + "'");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("bad.toml:3:"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out" / "work_precision.csv"));
}

TEST_F(BenchCli, UnknownBodyAndMissingSceneExit2) {
  const fs::path scene = write("pair.toml", kScene);
  Result r = run("bench --quick --scene '" + scene.string() + "' --body nobody -o '" + (dir_ / "o").string() + "'");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("free, pushed"), std::string::npos) << r.err;
  r = run("bench --quick --scene '" + (dir_ / "missing.toml").string() + "'");
  EXPECT_EQ(r.code, 2);
  r = run("bench --quick --body free");
  EXPECT_EQ(r.code, 2);
}

// `tumble bench` runs tumble-bench from tumble's folder: its help is
// tumble-bench's, and a tumble alone (a demo build) says what to build.
TEST_F(BenchCli, TumbleBenchRunsTheBenchTool) {
  const Result r = run("bench --help");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("tumble bench"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--scene"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--render"), std::string::npos) << r.out;
}

TEST_F(BenchCli, WithoutTheBenchToolTumbleBenchSaysWhatToBuild) {
  const fs::path alone = dir_ / "alone" / "tumble";
  fs::create_directories(alone.parent_path());
  fs::copy_file(tumble_bin(), alone);
  fs::permissions(alone, fs::perms::owner_all);
  const std::string cmd = "'" + alone.string() + "' bench --quick >/dev/null 2>'" + (dir_ / "err").string() + "'";
  const int st = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(st));
  EXPECT_EQ(WEXITSTATUS(st), 2);
  const std::string err = slurp(dir_ / "err");
  EXPECT_NE(err.find("the benchmark tool is not built"), std::string::npos) << err;
  EXPECT_NE(err.find("tumble-bench"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(dir_ / "out")) << "ran a study without the tool";
}

}  // namespace
