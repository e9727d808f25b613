// The bench studies. Each writes its CSV into the output folder and returns its
// rows so run() can chart and summarise them.
#pragma once

#include <cmath>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "bench/problems.hpp"

namespace tumble::bench {

struct Settings {
  bool quick = false;
  double min_batch_s = 0.02;  ///< each timed batch spans at least this much CPU, s
  int repeats = 5;            ///< timed batches per point (median taken)
  static Settings make(bool quick) {
    Settings s;
    s.quick = quick;
    s.min_batch_s = quick ? 0.002 : 0.02;
    s.repeats = quick ? 3 : 5;
    return s;
  }
};

/// One point of a work-precision curve. `method` is a tumble method name or a
/// peer label (bullet_*, ode_*); `param` is dt (s) or, for rk45, rtol.
struct WpRow {
  std::string problem, method, param_name;
  double param = 0, cpu_s = 0, angle = 0, energy = 0;
};

/// The fixed-step sweep on p, from p.dt_max (from p.duration for the closed
/// form, `exact` on a torque-free body) down 4 decades (--quick: 2), and at
/// most 1e6 steps (--quick: 1e5) per run.
std::vector<double> dt_grid(const Settings& st, const Problem& p, bool closed_form);
/// The rtol sweep of adaptive runs (tumble's pairs and adaptive peers): 1e-3 … 1e-12, 8 per
/// decade (--quick: 2 per decade), fine enough that the rtol grid does not decide the cheapest:
/// a run that just misses a tolerance costs the next point, at most 10^(1/40) ≈ 6 % more for a
/// 5th-order pair (4 per decade let grid luck alone move rk45 ÷ odeint's dopri5 by ±12 %).
std::vector<double> rtol_grid(const Settings& st);

std::vector<WpRow> work_precision(const std::vector<Problem>& problems, const Settings& st, std::ostream& log);
void write_work_precision_csv(const std::filesystem::path& file, const std::vector<WpRow>& rows);

/// Least-squares slope of log(error) against log(dt) over the points in the
/// asymptotic range (1e-11 < error < 1e-2); NaN with fewer than 2 such points.
struct OrderFit {
  std::string problem, method;
  double order_angle = 0, order_energy = 0;
};
std::vector<OrderFit> fit_orders(const std::vector<WpRow>& rows);
void write_orders_csv(const std::filesystem::path& file, const std::vector<OrderFit>& fits);

/// Stability map cell classes, in increasing badness.
enum class Cell { ok = 0, inaccurate = 1, wrong = 2, diverged = 3 };
const char* cell_name(Cell c);
struct StabilityRow {
  std::string method;
  double dt = 0, spin = 0, duration = 0, error = 0;
  int flips = 0;        ///< Π₂ sign changes seen at the method's step times
  int flips_exact = 0;  ///< the closed form's, seen at the same step times
  bool tipped = false;
  Cell cell = Cell::ok;
};
std::vector<StabilityRow> stability_map(const Settings& st, std::ostream& log);
void write_stability_csv(const std::filesystem::path& file, const std::vector<StabilityRow>& rows);

/// Energy and |L| relative error against step count on the T-handle at dt = 1e-3 s.
struct DriftRow {
  std::string method;
  long step = 0;
  double t = 0, energy = 0, momentum = 0;
};
std::vector<DriftRow> long_run_drift(const Settings& st, std::ostream& log);
void write_drift_csv(const std::filesystem::path& file, const std::vector<DriftRow>& rows);

/// First-flip time and flip count over 10 s on the T-handle against dt.
struct FlipRow {
  std::string method;
  double dt = 0, first_flip = 0, first_flip_exact = 0;
  int flips = 0, flips_exact = 0;
};
std::vector<FlipRow> dzhanibekov(const Settings& st, std::ostream& log);
void write_flips_csv(const std::filesystem::path& file, const std::vector<FlipRow>& rows);

/// method = "auto" on each problem at each tolerance: the pick, its predicted
/// and delivered error (rad) and CPU (s), the pilot's CPU (s), and the
/// cheapest of tumble's configurations in the work-precision rows `wp` that
/// meets the tolerance.
struct AutoRow {
  std::string problem;
  double tolerance = 0;
  std::string method, param_name;
  double param = 0, predicted_error = 0, error = 0, predicted_cpu_s = 0, cpu_s = 0, pilot_cpu_s = 0;
  std::string cheapest;       ///< "rk4 dt 0.001"; empty when no configuration met the tolerance
  double cheapest_cpu_s = NAN;      ///< its CPU in the sweep (the bare stepping loop)
  double cheapest_run_cpu_s = NAN;  ///< its CPU run as auto's pick is (a Propagator, guard included)
};
/// 1e-3 … 1e-8 (--quick: 1e-3, 1e-5, 1e-8).
std::vector<double> auto_tolerances(const Settings& st);
std::vector<AutoRow> auto_study(const std::vector<Problem>& problems, const std::vector<WpRow>& wp, const Settings& st,
                                std::ostream& log);
void write_auto_csv(const std::filesystem::path& file, const std::vector<AutoRow>& rows);
std::string auto_markdown(const std::vector<AutoRow>& rows);

/// io::atomic_write_file: `file` is the old one or the whole new one; throws io::IoError.
void write_text(const std::filesystem::path& file, const std::string& text);

}  // namespace tumble::bench
