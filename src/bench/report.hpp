// Tables drawn from the work-precision rows, and the work-precision part of a
// report (CSV, charts and summary sections) shared by `tumble bench` and
// `tumble bench --scene`.
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "bench/studies.hpp"

namespace tumble::bench {

/// The cheapest run of one contender (a tumble method or a peer configuration)
/// whose orientation error at the end is ≤ tolerance; param NaN when none is.
struct CheapestRow {
  std::string problem;
  double tolerance = 0;   ///< rad
  std::string who, kind;  ///< kind: "tumble" or "peer"
  std::string param_name;
  double param = 0, cpu_s = 0, angle = 0;
  bool winner = false;    ///< the cheapest of all contenders at this tolerance
};
/// Tolerances 1e-3 … 1e-10 rad of the summary.
std::vector<double> summary_tolerances();
std::vector<CheapestRow> cheapest_per_tolerance(const std::vector<WpRow>& rows, const std::vector<double>& tols);
/// Contenders as rows, tolerances as columns, the winner in bold and in a last row.
std::string cheapest_markdown(const std::vector<CheapestRow>& rows, const std::string& problem);
void write_cheapest_csv(const std::filesystem::path& file, const std::vector<CheapestRow>& rows);

/// Orientation error at the end for dt = 0.1, 0.01 and 0.001 s.
std::string error_at_dt_markdown(const std::vector<WpRow>& rows, const std::string& problem);

/// Runs the work-precision study on `problems` and writes work_precision.csv,
/// convergence_orders.csv, cheapest.csv and (when `plot`) the work-precision and
/// convergence and tolerance charts into dir. Returns the summary.md sections;
/// appends the charts to `pngs` and (when given) the rows to `rows`.
std::string work_precision_report(const std::vector<Problem>& problems, const Settings& st,
                                  const std::filesystem::path& dir, bool plot,
                                  std::vector<std::filesystem::path>& pngs, std::ostream& log,
                                  std::vector<WpRow>* rows = nullptr);

/// "3.14" with `prec` significant digits; "—" for NaN or inf.
std::string fmt(double v, int prec = 3);

}  // namespace tumble::bench
