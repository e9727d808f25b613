// Stability map: for each method a grid of dt × spin rate Ω, each cell
// classified ok / inaccurate / qualitatively wrong / diverged.
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "bench/flips.hpp"
#include "bench/peers/peers.hpp"
#include "bench/studies.hpp"
#include "core/dynamics.hpp"
#include "core/methods/free_rotation_exact.hpp"
#include "core/quaternion.hpp"

namespace tumble::bench {

const char* cell_name(Cell c) {
  switch (c) {
    case Cell::ok: return "ok";
    case Cell::inaccurate: return "inaccurate";
    case Cell::wrong: return "wrong";
    case Cell::diverged: return "diverged";
  }
  return "?";
}

std::vector<double> exact_flip_times(const RigidBodyModel& m, const BodyState& s0, double t_max) {
  const FreeRotationExact ex(m.inertia, s0.q, s0.L);
  const double period = ex.body_period();
  const double dt = std::isfinite(period) ? std::min(period / 2000, 1e-3) : 1e-3;
  std::vector<double> out;
  FlipCounter fc;
  const long n = static_cast<long>(std::ceil(t_max / dt));
  double prev_t = 0;
  for (long i = 0; i <= n; ++i) {
    const double t = std::min(t_max, static_cast<double>(i) * dt);
    const int before = fc.count;
    fc.observe(ex.momentum_body(t)[1], t);
    if (fc.count != before) out.push_back(0.5 * (prev_t + t));
    prev_t = t;
  }
  return out;
}

double mid_flip_duration(const std::vector<double>& flips, double target) {
  size_t k = 0;
  while (k < flips.size() && flips[k] <= target) ++k;
  if (k == flips.size()) return target;  // no flip after target within the sampled span
  const double lo = k > 0 ? flips[k - 1] : 0.0;
  return 0.5 * (lo + flips[k]);
}

namespace {

struct AxisRun {
  bool diverged = false;
  double max_tilt = 0;  // rad, between the spun principal axis and L
  FlipCounter flips;
  BodyState final;
};

// Steps a fresh stepper for T with n = round(T/dt) steps, watching divergence (non-finite
// or energy ×10), the tilt of principal axis `axis` from L, and the Π₂ flips.
AxisRun watch(const MakeStepper& make, const RigidBodyModel& m, const BodyState& s0, double T, double dt, int axis) {
  AxisRun r;
  const long n = std::max(1L, std::lround(T / dt));
  const double h = T / static_cast<double>(n);
  const double e0 = total_energy(m, s0);
  const std::unique_ptr<Stepper> stepper = make(m, s0);
  BodyState s = s0;
  r.flips.observe(momentum_body(s)[1], 0);
  for (long i = 0; i < n; ++i) {
    stepper->step(h);
    s = stepper->state();
    const double t = static_cast<double>(i + 1) * h;
    const double e = total_energy(m, s);
    if (!s.all_finite() || !std::isfinite(e) || std::abs(e) > 10 * std::abs(e0)) {
      r.diverged = true;
      break;
    }
    const Eigen::Vector3d pi = momentum_body(s);
    r.flips.observe(pi[1], t);
    if (axis != 1)
      r.max_tilt = std::max(r.max_tilt, std::atan2(std::hypot(pi[(axis + 1) % 3], pi[(axis + 2) % 3]), std::abs(pi[axis])));
  }
  r.final = s;
  return r;
}

}  // namespace

std::vector<StabilityRow> stability_map(const Settings& st, std::ostream& log) {
  const std::vector<double> dts = log_sweep(0.3, st.quick ? 1e-3 : 1e-4, 2);
  const std::vector<double> spins = st.quick ? log_sweep(100, 1, 1) : log_sweep(100, 1, 3);
  const RigidBodyModel m = diagonal_model("t_handle", {1, 2, 3});
  const std::vector<Contender> contenders = stepped_contenders();
  std::vector<StabilityRow> rows;
  for (double spin : spins) {
    const BodyState mid = spinning_state(m, spin * Eigen::Vector3d(0.001, 1, 0.001));
    const BodyState major = spinning_state(m, spin * Eigen::Vector3d(0.001, 0.001, 1));
    const BodyState minor = spinning_state(m, spin * Eigen::Vector3d(1, 0.001, 0.001));
    const std::vector<double> flips = exact_flip_times(m, mid, 10.0 * 3);
    const double T = mid_flip_duration(flips, 10.0);
    int flips_exact = 0;
    for (double f : flips) flips_exact += f <= T;
    const BodyState ref = exact_free_state(m, mid, T);
    const double e_ref = total_energy(m, ref);
    // A step longer than half a flip interval aliases the flips, so a method is
    // held to the closed form's flips seen at its own step times, not all of them.
    const FreeRotationExact ex(m.inertia, mid.q, mid.L);
    std::vector<int> flips_seen;
    for (double dt : dts) {
      const long n = std::max(1L, std::lround(T / dt));
      FlipCounter fc;
      for (long i = 0; i <= n; ++i) {
        const double t = T * static_cast<double>(i) / static_cast<double>(n);
        fc.observe(ex.momentum_body(t)[1], t);
      }
      flips_seen.push_back(fc.count);
    }
    for (const Contender& who : contenders)
      for (size_t d = 0; d < dts.size(); ++d) {
        const double dt = dts[d];
        StabilityRow row{who.name, dt, spin, T, 0, 0, flips_seen[d], false, Cell::ok};
        const AxisRun a = watch(who.make, m, mid, T, dt, 1);
        const AxisRun b = a.diverged ? a : watch(who.make, m, major, T, dt, 2);
        const AxisRun c = a.diverged || b.diverged ? a : watch(who.make, m, minor, T, dt, 0);
        row.flips = a.flips.count;
        row.tipped = b.max_tilt > 0.1 || c.max_tilt > 0.1;
        if (a.diverged || b.diverged || c.diverged) {
          row.cell = Cell::diverged;
          row.error = NAN;
        } else {
          row.error = std::max(rotation_angle_between(a.final.q, ref.q),
                               std::abs(total_energy(m, a.final) - e_ref) / std::abs(e_ref));
          row.cell = row.tipped || row.flips != row.flips_exact ? Cell::wrong
                     : row.error > 0.01                     ? Cell::inaccurate
                                                            : Cell::ok;
        }
        rows.push_back(row);
      }
    log << "  stability spin " << spin << " rad/s: duration " << T << " s, " << flips_exact << " exact flips\n";
  }
  return rows;
}

void write_stability_csv(const std::filesystem::path& file, const std::vector<StabilityRow>& rows) {
  std::ostringstream f;
  f.precision(10);
  f << "method,dt,spin_rad_s,duration_s,cell,cell_name,error,flips,flips_exact,tipped\n";
  for (const StabilityRow& r : rows)
    f << r.method << ',' << r.dt << ',' << r.spin << ',' << r.duration << ',' << static_cast<int>(r.cell) << ','
      << cell_name(r.cell) << ',' << r.error << ',' << r.flips << ',' << r.flips_exact << ',' << r.tipped << '\n';
  write_text(file, f.str());
}

}  // namespace tumble::bench
