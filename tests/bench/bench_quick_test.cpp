// `tumble bench --quick` end to end: runs the studies into a temp folder once,
// then checks the CSVs it wrote.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <unistd.h>

#include "bench/bench.hpp"
#include "core/integrator.hpp"

namespace {

namespace fs = std::filesystem;
using Row = std::map<std::string, std::string>;

std::vector<Row> read_csv(const fs::path& file) {
  std::ifstream f(file);
  std::vector<Row> rows;
  std::string line;
  std::vector<std::string> header;
  auto split = [](const std::string& s) {
    std::vector<std::string> v;
    std::stringstream ss(s);
    std::string cell;
    while (std::getline(ss, cell, ',')) v.push_back(cell);
    return v;
  };
  if (std::getline(f, line)) header = split(line);
  while (std::getline(f, line)) {
    const auto cells = split(line);
    Row r;
    for (size_t i = 0; i < header.size() && i < cells.size(); ++i) r[header[i]] = cells[i];
    rows.push_back(r);
  }
  return rows;
}

double num(const Row& r, const std::string& k) { return std::stod(r.at(k)); }

class BenchQuick : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("tumble_bench_quick_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    std::ostringstream log;
    rc_ = tumble::bench::run({true, dir_}, log);
  }
  // TUMBLE_BENCH_KEEP=1 keeps the output for inspection.
  static void TearDownTestSuite() {
    if (!std::getenv("TUMBLE_BENCH_KEEP")) fs::remove_all(dir_);
  }
  static fs::path dir_;
  static int rc_;
};
fs::path BenchQuick::dir_;
int BenchQuick::rc_ = -1;

TEST_F(BenchQuick, WritesEveryMethodAndProblem) {
  ASSERT_EQ(rc_, 0);
  for (const char* f : {"work_precision.csv", "stability_map.csv", "drift.csv", "dzhanibekov.csv", "summary.md"})
    EXPECT_TRUE(fs::exists(dir_ / f)) << f;
  std::set<std::pair<std::string, std::string>> seen;
  for (const Row& r : read_csv(dir_ / "work_precision.csv")) seen.insert({r.at("problem"), r.at("method")});
  std::set<std::string> stab;
  for (const Row& r : read_csv(dir_ / "stability_map.csv")) stab.insert(r.at("method"));
  for (const char* p : {"t_handle", "symmetric_top", "forced"})
    for (tumble::Method m : tumble::kAllMethods) {
      EXPECT_TRUE(seen.count({p, std::string(tumble::method_name(m))})) << p << " " << tumble::method_name(m);
      EXPECT_TRUE(stab.count(std::string(tumble::method_name(m))));
    }
}

TEST_F(BenchQuick, ErrorsFiniteWhereStabilityMapSaysOk) {
  ASSERT_EQ(rc_, 0);
  std::map<std::pair<std::string, double>, std::string> ok_at_10;  // (method, dt) at Ω = 10 rad/s
  for (const Row& r : read_csv(dir_ / "stability_map.csv")) {
    if (r.at("cell_name") == "ok") {
      EXPECT_TRUE(std::isfinite(num(r, "error"))) << r.at("method") << " " << r.at("dt");
    }
    if (std::abs(num(r, "spin_rad_s") - 10) < 1e-9) ok_at_10[{r.at("method"), num(r, "dt")}] = r.at("cell_name");
  }
  // The work-precision T-handle is the Ω = 10 row: where the map says ok at a
  // dt at least as large, that run must be finite too.
  for (const Row& r : read_csv(dir_ / "work_precision.csv")) {
    if (r.at("problem") != "t_handle" || r.at("param_name") != "dt") continue;
    for (const auto& [key, cell] : ok_at_10)
      if (key.first == r.at("method") && cell == "ok" && key.second >= num(r, "param") * (1 - 1e-9)) {
        EXPECT_TRUE(std::isfinite(num(r, "angle_err_rad"))) << r.at("method") << " dt " << r.at("param");
        break;
      }
  }
}

TEST_F(BenchQuick, ExactIsBestAndErrorsFallWithDt) {
  ASSERT_EQ(rc_, 0);
  std::map<std::string, std::vector<std::pair<double, Row>>> by;  // method -> (param, row), T-handle
  for (const Row& r : read_csv(dir_ / "work_precision.csv"))
    if (r.at("problem") == "t_handle") by[r.at("method")].push_back({num(r, "param"), r});
  ASSERT_TRUE(by.count("exact"));
  // The T-handle sits next to the separatrix: the flow amplifies a relative
  // perturbation by ~1e7 over 10 s (rk45 at rtol 1e-9 ends ~1e-2 rad off), so
  // round-off of stepped methods (exact included) floors near 1e-7 rad.
  const double floor = 1e-7;
  for (const auto& [param, ex] : by["exact"])
    for (tumble::Method m : tumble::kAllMethods) {
      const std::string name(tumble::method_name(m));
      if (name == "exact" || tumble::method_info(m).adaptive) continue;
      for (const auto& [p2, other] : by[name])
        if (std::abs(p2 / param - 1) < 1e-9 && std::isfinite(num(other, "angle_err_rad"))) {
          EXPECT_LE(num(ex, "angle_err_rad"), std::max(num(other, "angle_err_rad"), floor)) << name << " dt " << param;
        }
    }
  for (auto& [method, pts] : by) {
    if (!tumble::parse_method(method)) continue;  // peers: shown, not required
    std::sort(pts.begin(), pts.end(), [](auto& a, auto& b) { return a.first > b.first; });
    for (size_t i = 0; i + 1 < pts.size(); ++i) {
      // In the asymptotic range (above round-off, below saturation) a smaller
      // step must not be less accurate. An adaptive pair's error follows rtol
      // within its band, not point by point (its step sequence changes with
      // rtol; near the T-handle's flips half a decade of rtol can end 1.3× worse).
      const double big = num(pts[i].second, "angle_err_rad"), small = num(pts[i + 1].second, "angle_err_rad");
      const bool adaptive = pts[i].second.at("param_name") == "rtol";
      if (method != "exact" && std::isfinite(big) && big > floor && big < 0.1) {
        EXPECT_LE(small, (adaptive ? 2.0 : 1.1) * big) << method << " at " << pts[i + 1].first;
      }
    }
    const double e_first = num(pts.front().second, "energy_rel_err"), e_last = num(pts.back().second, "energy_rel_err");
    // Over the whole sweep the energy error falls, unless it starts at round-off.
    if (std::isfinite(e_first) && e_first > 1e-12) {
      EXPECT_LT(e_last, e_first) << method;
    }
  }
}

// Boost.odeint is always built (header-only): its three configurations are on
// the work-precision, convergence (dt rows), stability and flip studies.
TEST_F(BenchQuick, OdeintPeersOnEveryStudy) {
  ASSERT_EQ(rc_, 0);
  const std::vector<std::string> odeint = {"odeint_rk4_world", "odeint_rk4_body", "odeint_dopri5_body"};
  std::map<std::string, std::map<double, double>> err;  // label -> param -> angle error, T-handle
  std::map<std::string, std::string> param_name;
  for (const Row& r : read_csv(dir_ / "work_precision.csv"))
    if (r.at("problem") == "t_handle") err[r.at("method")][num(r, "param")] = num(r, "angle_err_rad"),
                                       param_name[r.at("method")] = r.at("param_name");
  for (const std::string& l : odeint) {
    ASSERT_TRUE(err.count(l)) << l;
    EXPECT_GE(err[l].size(), 4u) << l;
    EXPECT_EQ(param_name[l], l == "odeint_dopri5_body" ? "rtol" : "dt") << l;
  }
  // Same method, same steps, different coordinates: Euler's
  // equations for Π keep the near-separatrix T-handle far more accurately than
  // (q, L_world) with q normalised inside f. At dt = 1e-3 s (10⁴ steps):
  auto at = [&](const std::string& l, double dt) {
    for (auto [p, e] : err[l])
      if (std::abs(p / dt - 1) < 1e-9) return e;
    return std::nan("");
  };
  const double body = at("odeint_rk4_body", 1e-3), world = at("odeint_rk4_world", 1e-3);
  EXPECT_LT(body, 1e-7);
  EXPECT_LT(100 * body, world);
  // Fourth order: 10× smaller step, ≥ 10³× smaller error, in the asymptotic range.
  EXPECT_LT(1e3 * body, at("odeint_rk4_body", 1e-2));
  std::set<std::string> stab, flips;
  for (const Row& r : read_csv(dir_ / "stability_map.csv")) stab.insert(r.at("method"));
  for (const Row& r : read_csv(dir_ / "dzhanibekov.csv")) flips.insert(r.at("method"));
  for (const std::string& l : odeint) {
    EXPECT_TRUE(stab.count(l)) << l;
    EXPECT_TRUE(flips.count(l)) << l;
  }
}

// cheapest.csv: per problem and tolerance, every contender once and exactly one
// winner, the cheapest of those that reached the tolerance.
TEST_F(BenchQuick, CheapestTableHasOneWinnerPerTolerance) {
  ASSERT_EQ(rc_, 0);
  std::map<std::pair<std::string, double>, std::vector<Row>> by;
  for (const Row& r : read_csv(dir_ / "cheapest.csv")) by[{r.at("problem"), num(r, "tolerance_rad")}].push_back(r);
  ASSERT_EQ(by.size(), 6u * 8u);  // 6 problems × 1e-3 … 1e-10
  for (const auto& [key, rows] : by) {
    int winners = 0;
    double best = INFINITY, win_cpu = NAN;
    for (const Row& r : rows) {
      const double cpu = num(r, "cpu_s");
      if (std::isfinite(cpu)) {
        best = std::min(best, cpu);
        EXPECT_LE(num(r, "angle_err_rad"), key.second) << r.at("method");
      }
      if (r.at("winner") == "1") ++winners, win_cpu = cpu;
    }
    if (std::isfinite(best)) {
      EXPECT_EQ(winners, 1) << key.first << " " << key.second;
      EXPECT_EQ(win_cpu, best);
    }
  }
  // Loose tolerances are reached by someone on every problem.
  EXPECT_TRUE(std::any_of(by[{"t_handle", 1e-3}].begin(), by[{"t_handle", 1e-3}].end(),
                          [](const Row& r) { return r.at("winner") == "1"; }));
}

TEST_F(BenchQuick, EulerEnergyGrowsMidpointDoesNot) {
  ASSERT_EQ(rc_, 0);
  std::map<std::string, std::vector<Row>> by;
  for (const Row& r : read_csv(dir_ / "drift.csv")) by[r.at("method")].push_back(r);
  const auto& eu = by["euler"];
  ASSERT_GE(eu.size(), 10u);
  EXPECT_GT(num(eu.back(), "energy_rel_err"), 100 * num(eu[5], "energy_rel_err"));
  EXPECT_GT(num(eu.back(), "energy_rel_err"), 1e-2);
  for (const Row& r : by["implicit_midpoint"]) EXPECT_LT(num(r, "energy_rel_err"), 1e-12) << r.at("step");
}

// auto's picks meet their tolerance when run on every bench problem, and it
// predicted their error within a factor of 30 (the prediction is an estimate,
// the check is not); each row names the cheapest configuration it is set against.
TEST_F(BenchQuick, AutoPicksMeetTheirTolerance) {
  ASSERT_EQ(rc_, 0);
  const auto rows = read_csv(dir_ / "auto.csv");
  ASSERT_EQ(rows.size(), 6u * 3u);  // 6 problems × 1e-3, 1e-5, 1e-8
  std::set<std::string> problems;
  for (const Row& r : rows) {
    problems.insert(r.at("problem"));
    EXPECT_TRUE(tumble::parse_method(r.at("method")).has_value()) << r.at("method");
    EXPECT_LE(num(r, "error"), num(r, "tolerance")) << r.at("problem") << " " << r.at("method");
    EXPECT_LE(num(r, "predicted_error"), num(r, "tolerance"));
    if (num(r, "predicted_error") > 0) {
      EXPECT_LT(num(r, "error"), 30 * num(r, "predicted_error")) << r.at("problem") << " " << r.at("method");
    }
    EXPECT_GT(num(r, "cpu_s"), 0);
    EXPECT_GE(num(r, "pilot_cpu_s"), 0);
    EXPECT_FALSE(r.at("cheapest").empty()) << r.at("problem") << " " << r.at("tolerance");
    // The ratio's denominator is the cheapest configuration run as auto's pick is.
    EXPECT_GT(num(r, "cheapest_run_cpu_s"), 0);
    EXPECT_NEAR(num(r, "whole_over_cheapest"), num(r, "whole_cpu_s") / num(r, "cheapest_run_cpu_s"),
                1e-4 * num(r, "whole_over_cheapest"));
  }
  EXPECT_EQ(problems.size(), 6u);
}

}  // namespace
