// The accuracy table of docs/methods.md, computed (`tumble_docs accuracy docs/methods.md`)
// so no figure in it is copied by hand.
#include <cmath>
#include <cstdio>
#include <sstream>

#include "bench/bench.hpp"
#include "bench/peers/peers.hpp"
#include "base/error.hpp"
#include "core/methods/embedded_rk.hpp"
#include "base/format.hpp"

namespace tumble::bench {

namespace {

// As the docs write them: 0.556, 1.57e-3, 0.
std::string sci(double v) {
  if (!std::isfinite(v)) return "diverged";
  if (v == 0) return "0";
  if (v >= 0.01) return format_number(v, 3);
  std::string s = format_number(v, 2, 'e');  // 1.57e-03 -> 1.57e-3
  const size_t e = s.find("e-0");
  if (e != std::string::npos) s.erase(e + 2, 1);
  return s;
}

// CPU figures: whole nanoseconds from 100 on (3.1e+02 reads badly).
std::string ns(double v) { return v < 100 ? format_number(v, 3) : format_number(v, 0, 'f'); }

constexpr double kDts[] = {1e-1, 1e-2, 1e-3};
constexpr double kRtol = 1e-9;

struct Line {
  std::string name;
  double err[3];
  std::string cost;
};

// Errors at the three steps of a fixed-step run, and ns/step at the last.
Line fixed_line(const std::string& name, const Problem& p,
                const std::function<BodyState(const Problem&, double dt)>& run) {
  Line l{name, {}, ""};
  for (int i = 0; i < 3; ++i) l.err[i] = errors(p, run(p, kDts[i])).angle;
  if (std::isfinite(l.err[2])) {
    const double cpu = median_cpu_seconds([&] { run(p, kDts[2]); }, 0.02, 5);
    l.cost = ns(1e9 * cpu / std::round(p.duration / kDts[2]));
  }
  return l;
}

}  // namespace

std::string readme_accuracy_table(std::ostream& log) {
  const Problem p = t_handle_problem();
  std::vector<Line> lines;
  for (Method m : kAllMethods) {
    const std::string name(method_name(m));
    if (!method_info(m).adaptive) {
      lines.push_back(fixed_line(name, p, [m](const Problem& q, double dt) {
        return run_fixed(m, q.model, q.s0, q.duration, dt);
      }));
    } else {  // the scene's defaults: rtol 1e-9, atol 1e-12, whatever dt
      AdaptiveOptions o;
      o.rtol = kRtol;
      long steps = 0;
      BodyState s;
      auto once = [&] {
        const auto r = method_info(m).adaptive(p.model, p.s0, 0.0, o);
        s = r->advance_to(p.duration);
        steps = r->accepted() + r->rejected();
      };
      once();
      const double e = errors(p, s).angle, cpu = median_cpu_seconds(once, 0.02, 5);
      lines.push_back({name + " (adaptive: rtol 1e-9, atol 1e-12)", {e, e, e},
                       ns(1e9 * cpu / static_cast<double>(steps)) + " (" + std::to_string(steps) + " steps)"});
    }
    log << "  readme table: " << lines.back().name << "\n";
  }
  for (const PeerConfig& c : peer_configs()) {
    if (c.param_name == "dt") {
      lines.push_back(fixed_line("peer " + c.label, p, [&c](const Problem& q, double dt) {
        return c.run(q.model, q.s0, q.duration, dt);
      }));
    } else {
      const double e = errors(p, c.run(p.model, p.s0, p.duration, kRtol)).angle;
      const double cpu = median_cpu_seconds([&] { c.run(p.model, p.s0, p.duration, kRtol); }, 0.02, 5);
      lines.push_back({"peer " + c.label + " (adaptive: rtol = atol = 1e-9)", {e, e, e}, ns(1e6 * cpu) + " µs per run"});
    }
    log << "  readme table: " << lines.back().name << "\n";
  }
  std::ostringstream o;
  o << "| method | dt = 1e-1 | dt = 1e-2 | dt = 1e-3 | ns/step at dt = 1e-3 |\n|---|---|---|---|---|\n";
  for (const Line& l : lines)
    o << "| " << l.name << " | " << sci(l.err[0]) << " | " << sci(l.err[1]) << " | " << sci(l.err[2]) << " | "
      << (l.cost.empty() ? "—" : l.cost) << " |\n";
  return o.str();
}

std::string replace_between_markers(const std::string& doc, const std::string& name, const std::string& body) {
  const std::string begin = "<!-- BEGIN " + name + " -->\n", end = "<!-- END " + name + " -->";
  const size_t b = doc.find(begin);
  if (b == std::string::npos) throw InputError("no line \"<!-- BEGIN " + name + " -->\" to replace after");
  const size_t from = b + begin.size();
  const size_t e = doc.find(end, from);
  if (e == std::string::npos) throw InputError("no line \"" + end + "\" after \"<!-- BEGIN " + name + " -->\"");
  std::string text = body;
  if (!text.empty() && text.back() != '\n') text += '\n';
  return doc.substr(0, from) + text + doc.substr(e);
}

}  // namespace tumble::bench
