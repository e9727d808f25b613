// `tumble bench`: work-precision, convergence, stability map, long-run drift,
// Dzhanibekov flips and optional peers, as CSV + gnuplot PNG + summary.md.
#pragma once

#include <filesystem>
#include <ostream>

namespace tumble::bench {

struct BenchOptions {
  bool quick = false;                            ///< smaller sweeps, shorter timing batches (CI)
  std::filesystem::path out_dir = "out/bench";   ///< created if missing
};

/// Runs every study, writes its files into out_dir and progress to `log`.
/// Returns 0 on success (also when gnuplot is missing: CSVs are still written).
int run(const BenchOptions& opt, std::ostream& log);

}  // namespace tumble::bench
