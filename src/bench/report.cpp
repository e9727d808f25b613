#include "bench/report.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "base/format.hpp"
#include "bench/charts.hpp"

namespace tumble::bench {

std::string fmt(double v, int prec) { return std::isfinite(v) ? format_number(v, prec) : "—"; }

std::vector<double> summary_tolerances() { return {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10}; }

namespace {

// Contenders of `problem` in first-seen order (tumble's methods come first in the rows).
std::vector<std::string> contenders_of(const std::vector<WpRow>& rows, const std::string& problem) {
  std::vector<std::string> order;
  for (const WpRow& r : rows)
    if (r.problem == problem && std::find(order.begin(), order.end(), r.method) == order.end()) order.push_back(r.method);
  return order;
}

std::vector<std::string> problems_of(const std::vector<WpRow>& rows) {
  std::vector<std::string> order;
  for (const WpRow& r : rows)
    if (std::find(order.begin(), order.end(), r.problem) == order.end()) order.push_back(r.problem);
  return order;
}

}  // namespace

std::vector<CheapestRow> cheapest_per_tolerance(const std::vector<WpRow>& rows, const std::vector<double>& tols) {
  std::vector<CheapestRow> out;
  for (const std::string& problem : problems_of(rows))
    for (double tol : tols) {
      const size_t first = out.size();
      for (const std::string& who : contenders_of(rows, problem)) {
        const WpRow* best = nullptr;
        for (const WpRow& r : rows)
          if (r.problem == problem && r.method == who && r.angle <= tol && std::isfinite(r.cpu_s) &&
              (!best || r.cpu_s < best->cpu_s))
            best = &r;
        CheapestRow c{problem, tol, who, parse_method(who) ? "tumble" : "peer", best ? best->param_name : "",
                      best ? best->param : NAN, best ? best->cpu_s : NAN, best ? best->angle : NAN, false};
        out.push_back(c);
      }
      CheapestRow* win = nullptr;
      for (size_t i = first; i < out.size(); ++i)
        if (std::isfinite(out[i].cpu_s) && (!win || out[i].cpu_s < win->cpu_s)) win = &out[i];
      if (win) win->winner = true;
    }
  return out;
}

namespace {

using Cells = std::map<std::pair<std::string, double>, const CheapestRow*>;

// CPU of `a` over CPU of `b` per tolerance (< 1: a is cheaper); empty names =
// the cheapest of tumble's methods over the cheapest peer. Empty when no cell has both.
std::string ratio_row(const std::string& title, Cells& cell, const std::vector<std::string>& who,
                      const std::vector<double>& tols, const std::string& a, const std::string& b) {
  std::string row = "| " + title + " |";
  bool any = false;
  for (double t : tols) {
    double ca = NAN, cb = NAN;
    for (const std::string& w : who) {
      const CheapestRow* c = cell[{w, t}];
      if (!c || !std::isfinite(c->cpu_s)) continue;
      const bool is_a = a.empty() ? c->kind == "tumble" : w == a, is_b = b.empty() ? c->kind == "peer" : w == b;
      if (is_a && !(c->cpu_s >= ca)) ca = c->cpu_s;
      if (is_b && !(c->cpu_s >= cb)) cb = c->cpu_s;
    }
    const bool both = std::isfinite(ca) && std::isfinite(cb);
    any = any || both;
    row += " " + (both ? fmt(ca / cb, 2) + "×" : std::string("—")) + " |";
  }
  return any ? row + "\n" : "";
}

}  // namespace

std::string cheapest_markdown(const std::vector<CheapestRow>& rows, const std::string& problem) {
  std::vector<double> tols;
  std::vector<std::string> who;
  Cells cell;
  for (const CheapestRow& r : rows) {
    if (r.problem != problem) continue;
    if (std::find(tols.begin(), tols.end(), r.tolerance) == tols.end()) tols.push_back(r.tolerance);
    if (std::find(who.begin(), who.end(), r.who) == who.end()) who.push_back(r.who);
    cell[{r.who, r.tolerance}] = &r;
  }
  std::ostringstream o;
  o << "| method or peer |";
  for (double t : tols) o << " ≤ " << fmt(t) << " rad |";
  o << "\n|---|";
  for (size_t i = 0; i < tols.size(); ++i) o << "---|";
  o << "\n";
  std::map<double, std::string> winner;
  std::map<double, const CheapestRow*> best_peer;
  for (const std::string& w : who) {
    o << "| " << w << " |";
    for (double t : tols) {
      const CheapestRow* c = cell[{w, t}];
      if (!c || !std::isfinite(c->cpu_s)) {
        o << " — |";
        continue;
      }
      const double us = c->cpu_s * 1e6;
      const std::string cpu = (us < 1000 ? fmt(us) : std::to_string(std::lround(us))) + " µs";
      o << " " << (c->winner ? "**" + cpu + "**" : cpu) << " (" << c->param_name << " " << fmt(c->param) << ") |";
      if (c->winner) winner[t] = w;
      if (c->kind == "peer" && (!best_peer[t] || c->cpu_s < best_peer[t]->cpu_s)) best_peer[t] = c;
    }
    o << "\n";
  }
  o << "| **cheapest** |";
  for (double t : tols) o << " " << (winner.count(t) ? "**" + winner[t] + "**" : std::string("none")) << " |";
  o << "\n";
  if (std::any_of(rows.begin(), rows.end(), [&](const CheapestRow& r) { return r.problem == problem && r.kind == "peer"; })) {
    o << "| cheapest peer |";
    for (double t : tols) o << " " << (best_peer[t] ? best_peer[t]->who : std::string("none")) << " |";
    o << "\n" << ratio_row("tumble's cheapest ÷ cheapest peer", cell, who, tols, "", "");
    for (const auto& [ours, theirs] : {std::pair{"rk45", "odeint_dopri5_body"}, {"dop853", "odeint_dopri5_body"},
                                       {"rk4", "odeint_rk4_body"}})
      o << ratio_row(std::string(ours) + " ÷ " + theirs, cell, who, tols, ours, theirs);
  }
  return o.str();
}

void write_cheapest_csv(const std::filesystem::path& file, const std::vector<CheapestRow>& rows) {
  std::ostringstream f;
  f.precision(17);
  f << "problem,tolerance_rad,method,kind,param_name,param,cpu_s,angle_err_rad,winner\n";
  for (const CheapestRow& r : rows)
    f << r.problem << ',' << r.tolerance << ',' << r.who << ',' << r.kind << ',' << r.param_name << ',' << r.param
      << ',' << r.cpu_s << ',' << r.angle << ',' << (r.winner ? 1 : 0) << '\n';
  write_text(file, f.str());
}

std::string error_at_dt_markdown(const std::vector<WpRow>& rows, const std::string& problem) {
  const double dts[] = {1e-1, 1e-2, 1e-3};
  std::ostringstream o;
  o << "| method | err @ dt=0.1 s | err @ 0.01 s | err @ 0.001 s |\n|---|---|---|---|\n";
  std::map<std::string, std::map<int, double>> v;
  for (const WpRow& r : rows) {
    if (r.problem != problem || r.param_name != "dt") continue;
    for (int i = 0; i < 3; ++i)
      if (std::abs(r.param / dts[i] - 1) < 1e-6) v[r.method][i] = r.angle;
  }
  for (const std::string& m : contenders_of(rows, problem)) {
    if (!v.count(m)) continue;  // adaptive
    o << "| " << m << " |";
    for (int i = 0; i < 3; ++i) o << " " << (v[m].count(i) ? fmt(v[m][i]) : "—") << " |";
    o << "\n";
  }
  return o.str();
}

static std::string tolerance_markdown(const std::vector<WpRow>& rows) {
  std::ostringstream o;
  o << "## Tolerance proportionality (tolerance.png)\n\nOrientation error at the end over rtol (atol = rtol) for "
       "rtol from 1e-4 to 1e-10: within 10× of rtol means a ratio in [0.1, 10].\n\n| problem | adaptive method "
       "| smallest error/rtol | largest error/rtol | points |\n|---|---|---|---|---|\n";
  std::map<std::pair<std::string, std::string>, std::vector<double>> ratios;
  for (const WpRow& r : rows)
    if (r.param_name == "rtol" && r.param <= 1e-4 * (1 + 1e-9) && r.param >= 1e-10 * (1 - 1e-9))
      ratios[{r.problem, r.method}].push_back(r.angle / r.param);
  for (const auto& [key, v] : ratios)
    o << "| " << key.first << " | " << key.second << " | " << fmt(*std::min_element(v.begin(), v.end()), 2) << " | "
      << fmt(*std::max_element(v.begin(), v.end()), 2) << " | " << v.size() << " |\n";
  return o.str() + "\n";
}

std::string work_precision_report(const std::vector<Problem>& problems, const Settings& st,
                                  const std::filesystem::path& dir, bool plot,
                                  std::vector<std::filesystem::path>& pngs, std::ostream& log,
                                  std::vector<WpRow>* rows) {
  const std::vector<WpRow> wp = work_precision(problems, st, log);
  if (rows) *rows = wp;
  write_work_precision_csv(dir / "work_precision.csv", wp);
  const std::vector<OrderFit> fits = fit_orders(wp);
  write_orders_csv(dir / "convergence_orders.csv", fits);
  const std::vector<CheapestRow> cheap = cheapest_per_tolerance(wp, summary_tolerances());
  write_cheapest_csv(dir / "cheapest.csv", cheap);
  if (plot)
    for (auto v : {chart_work_precision(dir, wp, log), chart_convergence(dir, wp, fits, log), chart_tolerance(dir, wp, log)})
      pngs.insert(pngs.end(), v.begin(), v.end());

  std::ostringstream md;
  for (const Problem& p : problems)
    md << "## " << p.name << ": cheapest run reaching each orientation error at " << fmt(p.duration) << " s\n\n"
       << "CPU per run (µs) of the cheapest configuration of each method and peer whose orientation error at the end "
       << "is within the tolerance, its step or rtol in brackets; the cheapest of all in bold. (cheapest.csv)\n\n"
       << cheapest_markdown(cheap, p.name) << "\n";
  for (const Problem& p : problems)
    md << "## Orientation error (rad) at " << fmt(p.duration) << " s: " << p.name << "\n\n"
       << error_at_dt_markdown(wp, p.name) << "\n";
  md << tolerance_markdown(wp);
  md << "## Fitted orders (slope of log error vs log dt over errors in (1e-11, 1e-2))\n\n| problem | method | angle | "
        "energy |\n|---|---|---|---|\n";
  for (const OrderFit& f : fits)
    md << "| " << f.problem << " | " << f.method << " | " << fmt(f.order_angle) << " | " << fmt(f.order_energy)
       << " |\n";
  return md.str() + "\n";
}

}  // namespace tumble::bench
