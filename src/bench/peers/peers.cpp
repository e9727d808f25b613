// The registry: the engines in order, and what the bench asks of them all.
#include "bench/peers/peers.hpp"

#include <cmath>

namespace tumble::bench {

namespace {

std::vector<PeerEngine> engines() { return {odeint_engine(), bullet_engine(), ode_engine()}; }

}  // namespace

std::vector<PeerConfig> peer_configs() {
  std::vector<PeerConfig> v;
  for (PeerEngine& e : engines())
    for (PeerConfig& c : e.configs) v.push_back(std::move(c));
  return v;
}

std::vector<Contender> stepped_contenders() {
  std::vector<Contender> v;
  for (Method method : kAllMethods)
    v.push_back({std::string(method_name(method)), [method](const RigidBodyModel& m, const BodyState& s0) {
                   return method_stepper(method, m, s0);
                 }});
  for (const PeerConfig& c : peer_configs()) v.push_back({c.label, c.make});
  return v;
}

std::vector<std::string> peers_found() {
  std::vector<std::string> v;
  for (const PeerEngine& e : engines())
    if (!e.found.empty()) v.push_back(e.found);
  return v;
}

std::string peer_settings_markdown() {
  std::string s;
  for (const PeerEngine& e : engines()) s += e.settings;
  s += "- Bullet and ODE run on torque-free problems only; odeint also on the forced ones (the same right-hand side, "
       "forces and reference as tumble's). Bullet and ODE CPU time covers creating the world and body and all steps "
       "of one run.\n";
  return s;
}

std::vector<WpRow> peer_work_precision(const Problem& p, const Settings& st, std::ostream& log) {
  std::vector<WpRow> rows;
  for (const PeerConfig& c : peer_configs()) {
    if (!p.torque_free && !c.forces) continue;
    const std::vector<double> params = c.param_name == "rtol" ? rtol_grid(st) : dt_grid(st, p, false);
    for (double par : params) {
      BodyState s;
      auto once = [&] { s = c.run(p.model, p.s0, p.duration, par); };
      once();
      const Errors err = errors(p, s);
      const double cpu = std::isfinite(err.angle) ? median_cpu_seconds(once, st.min_batch_s, st.repeats) : NAN;
      rows.push_back({p.name, c.label, c.param_name, par, cpu, err.angle, err.energy});
    }
    log << "  work-precision " << p.name << " " << c.label << ": " << params.size() << " points\n";
  }
  return rows;
}

}  // namespace tumble::bench
