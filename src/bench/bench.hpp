// `tumble bench`: work-precision, convergence, stability map, long-run drift,
// Dzhanibekov flips and optional peers, as CSV + gnuplot PNG + summary.md.
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "bench/problems.hpp"

namespace tumble::bench {

struct BenchOptions {
  bool quick = false;                            ///< smaller sweeps, shorter timing batches (CI)
  std::filesystem::path out_dir = "out/bench";   ///< created if missing
};

/// Runs every study, writes its files into out_dir and progress to `log`.
/// Returns 0 on success (also when gnuplot is missing: CSVs are still written).
int run(const BenchOptions& opt, std::ostream& log);

/// `tumble bench --scene`: the work-precision study alone (every method × a dt
/// sweep, rk45 × rtol, peers on torque-free bodies) on `problems`, one per body
/// of the user's scene: work_precision.csv, convergence_orders.csv,
/// cheapest.csv, charts and summary.md in out_dir.
int run_problems(const BenchOptions& opt, const std::string& title, const std::vector<Problem>& problems,
                 std::ostream& log);

/// docs/methods.md's "How accurate is each method on the reference problem?" table
/// (markdown): orientation error at 10 s on the T-handle of every method and
/// peer at dt = 0.1, 0.01, 0.001 s (adaptive: at rtol 1e-9), and ns per step at
/// dt = 1e-3 s (median CPU).
std::string readme_accuracy_table(std::ostream& log);

/// `doc` with the lines strictly between "<!-- BEGIN name -->" and
/// "<!-- END name -->" replaced by `body`. Throws InputError naming the
/// missing marker.
std::string replace_between_markers(const std::string& doc, const std::string& name, const std::string& body);

}  // namespace tumble::bench
