// rk45 against Boost.odeint's runge_kutta_dopri5 (the bench's
// odeint_dopri5_body: make_controlled(atol = rtol, rtol) + integrate_adaptive)
// on the T-handle and the forced T-handle, at 8 rtols per decade: delivered
// orientation error at the end, accepted and rejected steps, right-hand side
// evaluations, median thread CPU per run and per evaluation. Then, per target
// error 1e-3..1e-8, the CPU of each at that error, interpolated log-log between
// the sweep's points (no grid luck), and the ratio ours / odeint.
// Optional argument: `dop853` also sweeps dop853; `rk4` measures rk4's
// cheapest dt at 1e-10 rad on the T-handle (dt sweep 24 per decade);
// `auto [problem]`: instead, the bench's own work-precision sweep and auto study
// (full settings) on the scene problems (or the one named), as auto.csv.
// Run by scripts/adaptive_study.sh (the target tumble_adaptive_study).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include <boost/numeric/odeint.hpp>

#include "bench/problems.hpp"
#include "bench/studies.hpp"
#include "core/body_frame.hpp"
#include "core/dynamics.hpp"
#include "core/methods/embedded_rk.hpp"

using namespace tumble;
namespace odeint = boost::numeric::odeint;

namespace {

using State = std::array<double, 13>;  // q (x, y, z, w), Π, c, P: the bench peer's forced layout

// The bench peer's right-hand sides, counting evaluations.
struct Rhs {
  const RigidBodyModel* m;
  long* evals;
  void operator()(const State& x, State& dx, double t) const {
    ++*evals;
    if (m->forces.empty()) {  // the torque-free body formulation (odeint_peer.cpp's BodyRhs)
      const Eigen::Vector3d pi(x[4], x[5], x[6]);
      const Eigen::Vector3d w = m->inv_inertia.cwiseProduct(pi);
      const Eigen::Vector3d qv(x[0], x[1], x[2]);
      const Eigen::Vector3d dv = 0.5 * (x[3] * w + qv.cross(w));
      const Eigen::Vector3d dpi = pi.cross(w);
      dx = {dv.x(), dv.y(), dv.z(), -0.5 * qv.dot(w), dpi.x(), dpi.y(), dpi.z(), 0, 0, 0, 0, 0, 0};
      return;
    }
    BodyCoords b;
    b.q.coeffs() << x[0], x[1], x[2], x[3];
    b.pi = {x[4], x[5], x[6]};
    b.c = {x[7], x[8], x[9]};
    b.P = {x[10], x[11], x[12]};
    const BodyRate d = body_rate(*m, b, t);
    dx = {d.dq[0], d.dq[1], d.dq[2], d.dq[3], d.dpi.x(), d.dpi.y(), d.dpi.z(),
          d.dc.x(), d.dc.y(), d.dc.z(), d.dP.x(), d.dP.y(), d.dP.z()};
  }
};

struct Point {
  double rtol, err, cpu_us;
  long steps, rejected, evals;
};

// Torque-free: odeint's peer integrates 7 components; the 6 zero rates here
// would only add flops to its algebra, so the free case uses a 7-array.
template <int N>
BodyState odeint_run(const bench::Problem& p, double rtol, long& evals, long& steps) {
  using S = std::array<double, N>;
  const Eigen::Vector3d pi = momentum_body(p.s0);
  S x{};
  const double full[13] = {p.s0.q.x(), p.s0.q.y(), p.s0.q.z(), p.s0.q.w(), pi.x(), pi.y(), pi.z(),
                           p.s0.c.x(), p.s0.c.y(), p.s0.c.z(), p.s0.P.x(), p.s0.P.y(), p.s0.P.z()};
  std::copy(full, full + N, x.begin());
  auto f = [&](const S& y, S& dy, double t) {
    State a{}, d{};
    std::copy(y.begin(), y.end(), a.begin());
    Rhs{&p.model, &evals}(a, d, t);
    std::copy(d.begin(), d.begin() + N, dy.begin());
  };
  auto stepper = odeint::make_controlled(rtol, rtol, odeint::runge_kutta_dopri5<S>());
  steps = static_cast<long>(odeint::integrate_adaptive(stepper, f, x, 0.0, p.duration, 1e-3));
  BodyCoords b;
  b.q.coeffs() << x[0], x[1], x[2], x[3];
  b.q.normalize();
  b.pi = {x[4], x[5], x[6]};
  b.c = p.s0.c + p.duration * p.s0.P / p.model.mass;
  b.P = p.s0.P;
  if constexpr (N == 13) {
    b.c = {x[7], x[8], x[9]};
    b.P = {x[10], x[11], x[12]};
  }
  return state_of(b);
}

Point ours(const bench::Problem& p, bool dop, double rtol) {
  AdaptiveOptions o;
  o.rtol = o.atol = rtol;
  o.t_stop = p.duration;
  Point r{rtol, 0, 0, 0, 0, 0};
  auto once = [&] {
    auto it = dop ? make_dop853(p.model, p.s0, 0, o) : make_rk45(p.model, p.s0, 0, o);
    const BodyState s = it->advance_to(p.duration);
    r.err = bench::errors(p, s).angle;
    r.steps = it->accepted(), r.rejected = it->rejected(), r.evals = it->evaluations();
  };
  once();
  r.cpu_us = 1e6 * bench::median_cpu_seconds(once, 0.01, 5);
  return r;
}

Point peer(const bench::Problem& p, double rtol) {
  Point r{rtol, 0, 0, 0, 0, 0};
  auto once = [&] {
    long evals = 0, steps = 0;
    const BodyState s = p.torque_free ? odeint_run<7>(p, rtol, evals, steps) : odeint_run<13>(p, rtol, evals, steps);
    r.err = bench::errors(p, s).angle;
    r.steps = steps, r.evals = evals;
    r.rejected = (evals - 1) / 6 - steps;  // FSAL: 6 new evaluations per try, one at the start
  };
  once();
  r.cpu_us = 1e6 * bench::median_cpu_seconds(once, 0.01, 5);
  return r;
}

// CPU at error `tol`, log-log interpolated between the two sweep points that bracket it.
double cpu_at(const std::vector<Point>& v, double tol) {
  for (size_t i = 1; i < v.size(); ++i) {
    const Point &a = v[i - 1], &b = v[i];
    if (a.err >= tol && b.err <= tol && a.err > b.err) {
      const double w = std::log(a.err / tol) / std::log(a.err / b.err);
      return std::exp((1 - w) * std::log(a.cpu_us) + w * std::log(b.cpu_us));
    }
  }
  return NAN;
}

void print(const char* who, const std::vector<Point>& v) {
  for (const Point& r : v)
    std::printf("  %-7s rtol %.3g  err %.3g  steps %ld  rej %ld  evals %ld  cpu %.1f us  %.1f ns/eval\n", who, r.rtol,
                r.err, r.steps, r.rejected, r.evals, r.cpu_us, 1e3 * r.cpu_us / static_cast<double>(r.evals));
}

void rk4_at_1e10(const bench::Problem& p, const std::vector<Point>& dop) {
  double best = NAN, best_dt = 0, best_err = 0;
  for (double dt : bench::log_sweep(1e-2, 1e-4, 24)) {
    const BodyState s = bench::run_fixed(Method::rk4, p.model, p.s0, p.duration, dt);
    const double e = bench::errors(p, s).angle;
    if (e > 1e-10) continue;
    best_dt = dt, best_err = e;
    best = 1e6 * bench::median_cpu_seconds([&] { bench::run_fixed(Method::rk4, p.model, p.s0, p.duration, dt); }, 0.01, 5);
    break;
  }
  const double d = cpu_at(dop, 1e-10);
  std::printf("1e-10 rad on %s: rk4 dt %.3g (err %.3g) %.1f us; dop853 (interpolated) %.1f us; rk4/dop853 %.2f\n",
              p.name.c_str(), best_dt, best_err, best, d, best / d);
}

}  // namespace

// The bench's work_precision + auto_study (full settings) on the forced scenes.
int auto_rows(const char* only) {
  std::vector<bench::Problem> ps;
  for (bench::Problem& p : bench::scene_problems())
    if (!only || p.name == only) ps.push_back(std::move(p));
  for (const bench::Problem& p : ps)
    for (double rtol : {1e-2, 3e-3, 1e-3, 1e-4})
      for (bool dop : {false, true}) {
        const Point r = ours(p, dop, rtol);
        std::printf("%-12s %s rtol %.0e  err %.3g  steps %ld  rej %ld  evals %ld  cpu %.1f us\n", p.name.c_str(),
                    dop ? "dop853" : "rk45", rtol, r.err, r.steps, r.rejected, r.evals, r.cpu_us);
      }
  if (std::getenv("STUDY_STEPS_ONLY")) return 0;
  const bench::Settings st = bench::Settings::make(false);
  std::ostringstream log;
  const std::vector<bench::WpRow> wp = bench::work_precision(ps, st, log);
  for (const bench::Problem& p : ps)  // each method's cheapest configuration per tolerance
    for (double tol : bench::auto_tolerances(st)) {
      std::printf("%-12s tol %.0e:", p.name.c_str(), tol);
      for (Method m : kAllMethods) {
        const bench::WpRow* best = nullptr;
        for (const bench::WpRow& r : wp)
          if (r.problem == p.name && r.method == method_name(m) && r.angle <= tol && std::isfinite(r.cpu_s) &&
              (!best || r.cpu_s < best->cpu_s))
            best = &r;
        if (best) std::printf("  %s(%.3g) %.1f", best->method.c_str(), best->param, 1e6 * best->cpu_s);
      }
      std::printf("\n");
    }
  for (const bench::AutoRow& r : bench::auto_study(ps, wp, st, log))
    std::printf("%-12s tol %.0e  %s %s %.3g  err %.3g  pilot %.1f us  run %.1f us  cheapest %s %.1f us (sweep %.1f)  "
                "whole/cheapest %.2f\n",
                r.problem.c_str(), r.tolerance, r.method.c_str(), r.param_name.c_str(), r.param, r.error,
                1e6 * r.pilot_cpu_s, 1e6 * r.cpu_s, r.cheapest.c_str(), 1e6 * r.cheapest_run_cpu_s,
                1e6 * r.cheapest_cpu_s, (r.pilot_cpu_s + r.cpu_s) / r.cheapest_run_cpu_s);
  return 0;
}

int main(int argc, char** argv) {
  if (argc > 1 && !std::strcmp(argv[1], "auto")) return auto_rows(argc > 2 ? argv[2] : nullptr);
  bool with_dop = false, with_rk4 = false;
  for (int i = 1; i < argc; ++i) with_dop |= !std::strcmp(argv[i], "dop853"), with_rk4 |= !std::strcmp(argv[i], "rk4");
  const double tols[] = {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8};
  for (const bench::Problem& p : {bench::t_handle_problem(), bench::forced_problem()}) {
    std::vector<Point> a, b, c;
    for (double rtol : bench::log_sweep(1e-2, 1e-12, 8)) {
      a.push_back(ours(p, false, rtol));
      b.push_back(peer(p, rtol));
      if (with_dop || with_rk4) c.push_back(ours(p, true, rtol));
    }
    std::printf("%s\n", p.name.c_str());
    print("rk45", a);
    print("odeint", b);
    if (with_dop) print("dop853", c);
    std::printf("  tol     rk45_us  odeint_us  ratio%s\n", with_dop ? "  dop853_us  ratio" : "");
    for (double tol : tols) {
      const double x = cpu_at(a, tol), y = cpu_at(b, tol);
      std::printf("  %-6.0e  %7.1f  %9.1f  %5.2f", tol, x, y, x / y);
      if (with_dop) std::printf("  %9.1f  %5.2f", cpu_at(c, tol), cpu_at(c, tol) / y);
      std::printf("\n");
    }
    if (with_rk4 && p.torque_free) rk4_at_1e10(p, c);
  }
}
