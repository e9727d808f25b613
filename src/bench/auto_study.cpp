// method = "auto" checked the bench way: on every bench problem and at every
// tolerance from 1e-3 to 1e-8, what auto picks, its whole cost (the pilot that
// chose, then the run) against the cheapest of tumble's configurations in the
// work-precision sweep whose error meets the tolerance, and the error it delivers
// (orientation at the end against the problem's reference, as the sweep).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "bench/report.hpp"
#include "bench/studies.hpp"
#include "core/method_choice.hpp"
#include "core/propagator.hpp"

namespace tumble::bench {

namespace {

// The cheapest row of tumble's own methods on `problem` meeting `tol`, or nullptr.
const WpRow* cheapest_meeting(const std::vector<WpRow>& wp, const std::string& problem, double tol) {
  const WpRow* best = nullptr;
  for (const WpRow& r : wp)
    if (r.problem == problem && parse_method(r.method) && r.angle <= tol && std::isfinite(r.cpu_s) &&
        (!best || r.cpu_s < best->cpu_s))
      best = &r;
  return best;
}

// The sweep's configuration of row `r` as a run takes it (the sweep runs the
// pairs with atol = rtol, fixed steps at dt).
StepConfig config_of(const WpRow& r, double duration) {
  StepConfig c;
  c.method = *parse_method(r.method);
  c.dt = method_info(c.method).adaptive ? duration : r.param;
  c.rtol = c.atol = r.param;
  return c;
}

}  // namespace

std::vector<double> auto_tolerances(const Settings& st) {
  return st.quick ? std::vector<double>{1e-3, 1e-5, 1e-8} : std::vector<double>{1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8};
}

std::vector<AutoRow> auto_study(const std::vector<Problem>& problems, const std::vector<WpRow>& wp, const Settings& st,
                                std::ostream& log) {
  std::vector<AutoRow> rows;
  for (const Problem& p : problems)
    for (double tol : auto_tolerances(st)) {
      const ChoiceRequest req{p.duration, 0, tol, true};
      MethodChoice c;
      AutoRow row;
      row.problem = p.name;
      row.tolerance = tol;
      row.pilot_cpu_s = median_cpu_seconds([&] { c = choose_method(p.model, p.s0, req); }, st.min_batch_s, st.repeats);
      const bool adaptive = method_info(c.config.method).adaptive != nullptr;
      row.method = std::string(method_name(c.config.method));
      row.param_name = adaptive ? "rtol" : "dt";
      row.param = adaptive ? c.config.rtol : c.config.dt;
      row.predicted_error = c.error;
      row.predicted_cpu_s = c.cost_s;
      BodyState end;
      row.cpu_s = median_cpu_seconds([&] { end = Propagator(p.model, p.s0, c.config).advance_to(p.duration); },
                                     st.min_batch_s, st.repeats);
      row.error = errors(p, end).angle;
      if (const WpRow* best = cheapest_meeting(wp, p.name, tol)) {
        row.cheapest = best->method + " " + best->param_name + " " + fmt(best->param);
        row.cheapest_cpu_s = best->cpu_s;
        const StepConfig cheapest = config_of(*best, p.duration);
        row.cheapest_run_cpu_s = median_cpu_seconds(
            [&] { end = Propagator(p.model, p.s0, cheapest).advance_to(p.duration); }, st.min_batch_s, st.repeats);
      }
      rows.push_back(row);
      log << "  auto " << p.name << " at tolerance " << tol << ": " << row.method << " (" << row.param_name << " "
          << row.param << "), error " << row.error << " rad, whole cost / cheapest "
          << (row.pilot_cpu_s + row.cpu_s) / row.cheapest_run_cpu_s << "\n";
    }
  return rows;
}

void write_auto_csv(const std::filesystem::path& file, const std::vector<AutoRow>& rows) {
  std::ostringstream o;
  o.precision(6);
  o << "problem,tolerance,method,param_name,param,predicted_error,error,predicted_cpu_s,cpu_s,pilot_cpu_s,"
       "whole_cpu_s,cheapest,cheapest_cpu_s,cheapest_run_cpu_s,whole_over_cheapest\n";
  for (const AutoRow& r : rows) {
    const double whole = r.pilot_cpu_s + r.cpu_s;
    o << r.problem << "," << r.tolerance << "," << r.method << "," << r.param_name << "," << r.param << ","
      << r.predicted_error << "," << r.error << "," << r.predicted_cpu_s << "," << r.cpu_s << "," << r.pilot_cpu_s
      << "," << whole << "," << r.cheapest << "," << r.cheapest_cpu_s << "," << r.cheapest_run_cpu_s << ","
      << whole / r.cheapest_run_cpu_s << "\n";
  }
  write_text(file, o.str());
}

std::string auto_markdown(const std::vector<AutoRow>& rows) {
  std::ostringstream md;
  md << "\n## method = \"auto\" against the cheapest configuration (auto.csv)\n\nPer problem and tolerance: auto's "
        "pick, the error it delivers (orientation at the end, against the problem's reference), its whole CPU (the "
        "pilot that chose plus the run, medians) and the cheapest of tumble's configurations in the work-precision "
        "sweep whose error meets the tolerance (an oracle: it knows the errors), its CPU in the sweep's bare stepping "
        "loop and run as auto's pick is run (a Propagator, divergence guard included: the ratio's denominator, so "
        "both sides pay the same guard). Target: error ≤ tolerance and whole ÷ cheapest ≤ 2.\n\n"
     << "| problem | tolerance (rad) | pick | error | pilot (µs) | run (µs) | whole (µs) | cheapest | sweep CPU (µs) | "
        "run CPU (µs) | whole ÷ cheapest |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const AutoRow& a : rows) {
    const double whole = a.pilot_cpu_s + a.cpu_s;
    md << "| " << a.problem << " | " << fmt(a.tolerance) << " | " << a.method << " " << a.param_name << " "
       << fmt(a.param) << " | " << fmt(a.error) << (a.error <= a.tolerance ? "" : " **over**") << " | "
       << fmt(a.pilot_cpu_s * 1e6) << " | " << fmt(a.cpu_s * 1e6) << " | " << fmt(whole * 1e6) << " | "
       << (a.cheapest.empty() ? "none" : a.cheapest) << " | " << fmt(a.cheapest_cpu_s * 1e6) << " | "
       << fmt(a.cheapest_run_cpu_s * 1e6) << " | " << fmt(whole / a.cheapest_run_cpu_s, 2) << " |\n";
  }
  return md.str() + "\n";
}

}  // namespace tumble::bench
