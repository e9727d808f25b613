// Orchestrates the studies and writes summary.md.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <sstream>
#include <thread>

#include "bench/bench.hpp"
#include "bench/charts.hpp"
#include "bench/peers/peers.hpp"
#include "bench/report.hpp"
#include "bench/studies.hpp"

namespace tumble::bench {

namespace {

std::string stability_table(const std::vector<StabilityRow>& rows) {
  std::map<std::string, std::map<Cell, int>> count;
  std::map<std::string, double> largest_ok_at_10;
  std::vector<std::string> order;
  for (const StabilityRow& r : rows) {
    if (!count.count(r.method)) order.push_back(r.method);
    ++count[r.method][r.cell];
    if (std::abs(r.spin - 10) < 1e-6 && r.cell == Cell::ok) largest_ok_at_10[r.method] = std::max(largest_ok_at_10[r.method], r.dt);
  }
  std::ostringstream o;
  o << "| method | ok | inaccurate | wrong | diverged | largest ok dt at Ω = 10 rad/s (s) |\n|---|---|---|---|---|---|\n";
  for (const auto& m : order)
    o << "| " << m << " | " << count[m][Cell::ok] << " | " << count[m][Cell::inaccurate] << " | "
      << count[m][Cell::wrong] << " | " << count[m][Cell::diverged] << " | "
      << (largest_ok_at_10.count(m) ? fmt(largest_ok_at_10[m]) : "none") << " |\n";
  return o.str();
}

std::string header_markdown(const std::string& title, const Settings& st, const std::vector<Problem>& problems) {
  std::ostringstream md;
  md << title << "\n\n";
  md << "Machine: " << std::thread::hardware_concurrency() << " hardware threads; CPU time is this thread's "
     << "(CLOCK_THREAD_CPUTIME_ID), median of " << st.repeats << " batches of ≥ " << st.min_batch_s * 1e3
     << " ms each. Build: -O2 -ffp-contract=off (RelWithDebInfo unless stated).\n\n";
  md << "## Problems\n\n";
  for (const Problem& p : problems) {
    md << "- `" << p.name << "`: " << p.description;
    if (p.reference_check > 0)
      md << " (that dop853 at rtol 1e-13 is " << fmt(p.reference_check)
         << " rad from the closed form on the torque-free T-handle)";
    md << "\n";
  }
  const std::vector<std::string> peers = peers_found();
  md << "\n## Peers\n\nFound: ";
  for (size_t i = 0; i < peers.size(); ++i) md << (i ? "; " : "") << peers[i];
  md << "\n\n" << peer_settings_markdown() << "\n";
  return md.str();
}

// The Files and Wall time sections, then summary.md.
void finish(const std::filesystem::path& dir, const std::string& md, const std::string& csvs,
            const std::vector<std::filesystem::path>& pngs, bool plot,
            std::chrono::steady_clock::time_point wall0, std::ostream& log) {
  std::string out = md + "## Files\n\n- " + csvs + "\n";
  for (const auto& p : pngs) out += "- " + p.filename().string() + " (script " + p.stem().string() + ".gp)\n";
  if (!plot) out += "- no charts: gnuplot was not found\n";
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  out += "\nWall time: " + fmt(wall) + " s.\n";
  write_text(dir / "summary.md", out);
  log << "wrote " << (dir / "summary.md").string() << " (" << fmt(wall) << " s)\n";
}

}  // namespace

int run(const BenchOptions& opt, std::ostream& log) {
  const auto wall0 = std::chrono::steady_clock::now();
  const Settings st = Settings::make(opt.quick);
  std::filesystem::create_directories(opt.out_dir);
  const auto& dir = opt.out_dir;
  const bool plot = gnuplot_available();
  log << "tumble bench" << (opt.quick ? " --quick" : "") << " -> " << dir.string() << "\n";
  if (!plot) log << "gnuplot not found: writing CSV and summary.md only (install gnuplot for the charts)\n";
  const std::vector<std::string> peers = peers_found();
  log << "peers found: " << (peers.empty() ? std::string("none") : "") ;
  for (size_t i = 0; i < peers.size(); ++i) log << (i ? "; " : "") << peers[i];
  log << "\n";

  const std::vector<Problem> problems = all_problems();
  std::vector<std::filesystem::path> pngs;
  std::vector<WpRow> wp;
  const std::string wp_md = work_precision_report(problems, st, dir, plot, pngs, log, &wp);
  std::vector<StabilityRow> stab = stability_map(st, log);
  write_stability_csv(dir / "stability_map.csv", stab);
  std::vector<DriftRow> drift = long_run_drift(st, log);
  write_drift_csv(dir / "drift.csv", drift);
  std::vector<FlipRow> flips = dzhanibekov(st, log);
  write_flips_csv(dir / "dzhanibekov.csv", flips);
  std::vector<AutoRow> autos = auto_study(problems, wp, st, log);
  write_auto_csv(dir / "auto.csv", autos);

  if (plot) {
    for (auto v : {chart_stability(dir, stab, log), chart_drift(dir, drift, log), chart_flips(dir, flips, log)})
      pngs.insert(pngs.end(), v.begin(), v.end());
  }

  std::ostringstream md;
  md << header_markdown(std::string("# tumble bench") + (opt.quick ? " (--quick)" : ""), st, problems);
  md << "Targets on the T-handle: ≤ 1e-6 rad within 20 µs, ≤ 1e-9 rad within 200 µs. `exact` with "
     << "dt ≥ 1 s is a handful of closed-form steps.\n\n"
     << wp_md;
  md << "## Stability map (T-handle moments, spin Ω about the intermediate axis for ≈ 10 s ending between flips, "
     << "plus major/minor-axis spins with a 1e-3 tilt)\n\nok: error ≤ 1 % (max of orientation rad and relative energy); "
     << "inaccurate: > 1 %; wrong: flip count differs from the closed form's (both seen at the method's step times, so a step longer than half a flip interval is not blamed for aliasing) or a stable axis tilts > 0.1 rad; "
     << "diverged: non-finite or energy × 10. rk45, dop853 and odeint_dopri5_body here are fixed-step steps of their pairs.\n\n"
     << stability_table(stab) << "\n";
  md << "## Long-run drift (T-handle, dt = 1 ms)\n\nWorld L is a state variable with L' = 0 when torque-free, so every method keeps "
     << "it exactly; the |Π| column (Π = q* L q) shows |q| drift instead.\n\n| method | steps | |ΔE|/E at end | |Δ|Π||/|L| at end |\n|---|---|---|---|\n";
  std::map<std::string, DriftRow> last;
  for (const DriftRow& r : drift) last[r.method] = r;
  for (Method m : kAllMethods) {
    const DriftRow& r = last[std::string(method_name(m))];
    md << "| " << r.method << " | " << r.step << " | " << fmt(r.energy) << " | " << fmt(r.momentum) << " |\n";
  }
  md << auto_markdown(autos);
  finish(dir, md.str(),
         "work_precision.csv, convergence_orders.csv, cheapest.csv, stability_map.csv, drift.csv, dzhanibekov.csv, "
         "auto.csv",
         pngs, plot, wall0, log);
  return 0;
}

int run_problems(const BenchOptions& opt, const std::string& title, const std::vector<Problem>& problems,
                 std::ostream& log) {
  const auto wall0 = std::chrono::steady_clock::now();
  const Settings st = Settings::make(opt.quick);
  std::filesystem::create_directories(opt.out_dir);
  const bool plot = gnuplot_available();
  log << "tumble bench --scene " << title << (opt.quick ? " --quick" : "") << " -> " << opt.out_dir.string() << "\n";
  if (!plot) log << "gnuplot not found: writing CSV and summary.md only (install gnuplot for the charts)\n";
  std::vector<std::filesystem::path> pngs;
  const std::string wp_md = work_precision_report(problems, st, opt.out_dir, plot, pngs, log);
  finish(opt.out_dir,
         header_markdown("# tumble bench --scene " + title + (opt.quick ? " (--quick)" : ""), st, problems) + wp_md,
         "work_precision.csv, convergence_orders.csv, cheapest.csv", pngs, plot, wall0, log);
  return 0;
}

}  // namespace tumble::bench
