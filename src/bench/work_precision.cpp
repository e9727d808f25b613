// Work-precision (Hairer–Nørsett–Wanner I §II.10 style): CPU per run against
// error at the end, for every method on every problem, plus the fitted orders.
#include <cmath>
#include <map>
#include <sstream>

#include "bench/peers/peers.hpp"
#include "bench/studies.hpp"
#include "io/atomic_file.hpp"

namespace tumble::bench {

// Shared dt grid so methods can be compared point by point. The closed form
// starts at the whole run (a single step: its cost floor); the others at dt_max.
std::vector<double> dt_grid(const Settings& st, const Problem& p, bool closed_form) {
  const double hi = closed_form ? p.duration : p.dt_max;
  const double lo = std::max(p.dt_max * (st.quick ? 1e-2 : 1e-4), p.duration / (st.quick ? 1e5 : 1e6));
  return decade_grid(hi * (1 + 1e-9), lo * (1 - 1e-9), st.quick ? 2 : 3);
}

std::vector<double> rtol_grid(const Settings& st) {
  return st.quick ? log_sweep(1e-3, 1e-12, 2) : log_sweep(1e-3, 1e-12, 8);
}

std::vector<WpRow> work_precision(const std::vector<Problem>& problems, const Settings& st, std::ostream& log) {
  std::vector<WpRow> rows;
  for (const Problem& p : problems) {
    for (Method m : kAllMethods) {
      const MethodInfo& info = method_info(m);
      const bool adaptive = info.adaptive;
      const std::vector<double> params =
          adaptive ? rtol_grid(st) : dt_grid(st, p, info.closed_form_if_free && p.torque_free);
      for (double par : params) {
        BodyState s;
        auto once = [&] {
          s = adaptive ? run_adaptive(m, p.model, p.s0, p.duration, par) : run_fixed(m, p.model, p.s0, p.duration, par);
        };
        once();
        const Errors e = errors(p, s);
        // Diverged runs are not timed (their cost says nothing) but are kept as NaN.
        const double cpu = std::isfinite(e.angle) ? median_cpu_seconds(once, st.min_batch_s, st.repeats) : NAN;
        rows.push_back({p.name, std::string(method_name(m)), adaptive ? "rtol" : "dt", par, cpu, e.angle, e.energy});
      }
      log << "  work-precision " << p.name << " " << method_name(m) << ": " << params.size() << " points\n";
    }
    if (p.peers) {
      std::vector<WpRow> peer = peer_work_precision(p, st, log);
      rows.insert(rows.end(), peer.begin(), peer.end());
    }
  }
  return rows;
}

void write_text(const std::filesystem::path& file, const std::string& text) { io::atomic_write_file(file, text); }

void write_work_precision_csv(const std::filesystem::path& file, const std::vector<WpRow>& rows) {
  std::ostringstream f;
  f.precision(17);
  f << "problem,method,param_name,param,cpu_s,angle_err_rad,energy_rel_err\n";
  for (const WpRow& r : rows)
    f << r.problem << ',' << r.method << ',' << r.param_name << ',' << r.param << ',' << r.cpu_s << ','
      << r.angle << ',' << r.energy << '\n';
  write_text(file, f.str());
}

namespace {
double fit_slope(const std::vector<std::pair<double, double>>& pts) {
  std::vector<std::pair<double, double>> use;
  for (auto [dt, e] : pts)
    if (std::isfinite(e) && e > 1e-11 && e < 1e-2) use.emplace_back(std::log(dt), std::log(e));
  if (use.size() < 2) return NAN;
  double mx = 0, my = 0;
  for (auto [x, y] : use) mx += x, my += y;
  mx /= static_cast<double>(use.size());
  my /= static_cast<double>(use.size());
  double sxy = 0, sxx = 0;
  for (auto [x, y] : use) sxy += (x - mx) * (y - my), sxx += (x - mx) * (x - mx);
  return sxx > 0 ? sxy / sxx : NAN;
}
}  // namespace

std::vector<OrderFit> fit_orders(const std::vector<WpRow>& rows) {
  std::map<std::pair<std::string, std::string>, std::vector<const WpRow*>> groups;
  for (const WpRow& r : rows)
    if (r.param_name == "dt") groups[{r.problem, r.method}].push_back(&r);
  std::vector<OrderFit> out;
  for (const auto& [key, g] : groups) {
    std::vector<std::pair<double, double>> a, e;
    for (const WpRow* r : g) a.emplace_back(r->param, r->angle), e.emplace_back(r->param, r->energy);
    out.push_back({key.first, key.second, fit_slope(a), fit_slope(e)});
  }
  return out;
}

void write_orders_csv(const std::filesystem::path& file, const std::vector<OrderFit>& fits) {
  std::ostringstream f;
  f.precision(4);
  f << "problem,method,order_angle,order_energy\n";
  for (const OrderFit& o : fits) f << o.problem << ',' << o.method << ',' << o.order_angle << ',' << o.order_energy << '\n';
  write_text(file, f.str());
}

}  // namespace tumble::bench
