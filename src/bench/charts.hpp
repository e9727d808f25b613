// gnuplot charts (pngcairo). Each chart writes NAME.dat and NAME.gp next to
// NAME.png, so a chart can be re-drawn or restyled by hand.
#pragma once

#include <filesystem>
#include <ostream>
#include <vector>

#include "bench/studies.hpp"

namespace tumble::bench {

/// True when `gnuplot` runs from PATH.
bool gnuplot_available();

/// Each returns the PNG paths it produced (empty when gnuplot failed; the
/// failure is written to `log`).
std::vector<std::filesystem::path> chart_work_precision(const std::filesystem::path& dir, const std::vector<WpRow>& rows,
                                                        std::ostream& log);
std::vector<std::filesystem::path> chart_convergence(const std::filesystem::path& dir, const std::vector<WpRow>& rows,
                                                     const std::vector<OrderFit>& fits, std::ostream& log);
std::vector<std::filesystem::path> chart_stability(const std::filesystem::path& dir,
                                                   const std::vector<StabilityRow>& rows, std::ostream& log);
std::vector<std::filesystem::path> chart_drift(const std::filesystem::path& dir, const std::vector<DriftRow>& rows,
                                               std::ostream& log);
/// Orientation error at the end against rtol for every adaptive configuration
/// (tumble's pairs and the adaptive peers) on every problem, with rtol/10, rtol
/// and 10 rtol drawn for reference.
std::vector<std::filesystem::path> chart_tolerance(const std::filesystem::path& dir, const std::vector<WpRow>& rows,
                                                   std::ostream& log);
std::vector<std::filesystem::path> chart_flips(const std::filesystem::path& dir, const std::vector<FlipRow>& rows,
                                               std::ostream& log);

}  // namespace tumble::bench
