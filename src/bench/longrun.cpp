// Long-run drift of the invariants, and the Dzhanibekov flips against dt.
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "bench/flips.hpp"
#include "bench/peers/peers.hpp"
#include "bench/studies.hpp"
#include "core/dynamics.hpp"
#include "core/fixed_stepper.hpp"

namespace tumble::bench {

std::vector<DriftRow> long_run_drift(const Settings& st, std::ostream& log) {
  const Problem p = t_handle_problem();
  const double dt = 1e-3;
  const long n = st.quick ? 100'000 : 1'000'000;
  const double e0 = total_energy(p.model, p.s0), l0 = p.s0.L.norm();
  std::vector<DriftRow> rows;
  for (Method method : kAllMethods) {
    FixedStepper stepper(method, p.model, p.s0);  // as a run steps
    long next = 1;
    for (long i = 1; i <= n; ++i) {
      stepper.step(static_cast<double>(i - 1) * dt, dt);
      if (i != next && i != n) continue;
      const BodyState s = stepper.state();
      // Sampled 20 per decade of steps; Π = q̄ L as the dynamics use it, so a
      // drifting |q| shows up here even though world L itself is never changed.
      const double e = std::abs(total_energy(p.model, s) - e0) / e0;
      const double l = std::abs(momentum_body(s).norm() - l0) / l0;
      rows.push_back({std::string(method_name(method)), i, static_cast<double>(i) * dt, e, l});
      if (!std::isfinite(e)) break;
      while (next <= i) next = std::max(next + 1, static_cast<long>(std::ceil(static_cast<double>(next) * 1.122)));
    }
    log << "  drift " << method_name(method) << ": " << n << " steps, energy error at end " << rows.back().energy
        << "\n";
  }
  return rows;
}

void write_drift_csv(const std::filesystem::path& file, const std::vector<DriftRow>& rows) {
  std::ostringstream f;
  f.precision(10);
  f << "method,step,t_s,energy_rel_err,momentum_rel_err\n";
  for (const DriftRow& r : rows) f << r.method << ',' << r.step << ',' << r.t << ',' << r.energy << ',' << r.momentum << '\n';
  write_text(file, f.str());
}

std::vector<FlipRow> dzhanibekov(const Settings& st, std::ostream& log) {
  const Problem p = t_handle_problem();
  const std::vector<double> exact = exact_flip_times(p.model, p.s0, p.duration);
  const double first_exact = exact.empty() ? -1 : exact.front();
  std::vector<FlipRow> rows;
  for (const Contender& who : stepped_contenders()) {
    for (double dt : log_sweep(0.3, st.quick ? 1e-3 : 1e-4, 3)) {
      const long n = std::max(1L, std::lround(p.duration / dt));
      const double h = p.duration / static_cast<double>(n);
      const std::unique_ptr<Stepper> stepper = who.make(p.model, p.s0);
      BodyState s = p.s0;
      FlipCounter fc;
      fc.observe(momentum_body(s)[1], 0);
      for (long i = 0; i < n && s.all_finite(); ++i) {
        stepper->step(h);
        s = stepper->state();
        fc.observe(momentum_body(s)[1], static_cast<double>(i + 1) * h);
      }
      rows.push_back({who.name, dt, fc.first_time, first_exact, fc.count, static_cast<int>(exact.size())});
    }
  }
  log << "  dzhanibekov: exact " << exact.size() << " flips, first at " << first_exact << " s\n";
  return rows;
}

void write_flips_csv(const std::filesystem::path& file, const std::vector<FlipRow>& rows) {
  std::ostringstream f;
  f.precision(10);
  f << "method,dt,first_flip_s,flips,first_flip_exact_s,flips_exact\n";
  for (const FlipRow& r : rows)
    f << r.method << ',' << r.dt << ',' << r.first_flip << ',' << r.flips << ',' << r.first_flip_exact << ','
      << r.flips_exact << '\n';
  write_text(file, f.str());
}

}  // namespace tumble::bench
