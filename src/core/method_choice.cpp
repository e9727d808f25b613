#include "core/method_choice.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

#include "base/format.hpp"
#include "core/methods/embedded_rk.hpp"
#include "core/error.hpp"
#include "core/fixed_stepper.hpp"
#include "core/methods/free_rotation_exact.hpp"
#include "core/quaternion.hpp"

namespace tumble {

namespace {

constexpr double kSafety = 0.5;           // aim at half the tolerance
constexpr double kBoundSafety = 0.8;      // aim of an error bound (kicked_exact_estimate)
constexpr double kPilotBudgetS = 0.2;     // predicted CPU per candidate's pilot
constexpr double kMaxPilotSteps = 1 << 22;
constexpr double kRoundOff = 1e-13;       // end differences below this are round-off
constexpr double kAdaptiveMargin = 10;    // adaptive pairs run at rtol = tolerance / this
constexpr double kPriceWindows = 32;      // an adaptive pair is priced on 1/32 of the run
constexpr double kProbeWindows = 8;       // exact on a torqued body is probed on 1/8 of it
constexpr double kOrderWindow = 0.4;      // order_seen: |observed order - p| within this

}  // namespace

bool order_seen(double observed, int p) { return std::abs(observed - p) <= kOrderWindow; }

namespace {

// End state after `duration` with `cfg`, or nullopt when the run diverged.
std::optional<BodyState> run(const RigidBodyModel& m, const BodyState& s0, const StepConfig& cfg, double duration) {
  try {
    return Propagator(m, s0, cfg).advance_to(duration);
  } catch (const Diverged&) {
    return std::nullopt;
  }
}

// Steps a run really takes: n on the grid plus at most one partial step per
// sample (Propagator samples between grid points without moving the grid).
double run_steps(const ChoiceRequest& r, double n) {
  if (r.sample_interval <= 0 || r.sample_interval >= r.duration) return n;
  return n + std::ceil(r.duration / r.sample_interval * (1 - 1e-12));
}

StepConfig fixed_config(Method method, const ChoiceRequest& r, double n) {
  StepConfig c;
  c.method = method;
  c.dt = r.duration / n;
  return c;
}

// After each rung of the pilot ladder (n_k steps; d_k[i] = error(x at n_k[i],
// x at n_k[i+1])): true, with e's config, steps and error set, once the
// differences settle the step count for an order-p method.
bool ladder_settles(const std::vector<double>& n_k, const std::vector<double>& d_k, int p, const ChoiceRequest& r,
                    MethodEstimate& e) {
  const size_t k = d_k.size();
  const double d = d_k.back(), n = n_k.back();
  // Three runs agreeing far inside the tolerance (or at round-off, where no
  // order shows): the coarsest of them already meets it. This is how a method
  // that is exact for the scene (exact + kicks under gravity alone) qualifies.
  const double agree = std::max(kRoundOff, 1e-2 * kSafety * r.tolerance);
  if (d <= agree) {
    if (k < 2 || !(d_k[k - 2] <= agree)) return false;
    e.usable = true;
    e.config = fixed_config(e.method, r, n_k[k - 2]);
    e.steps = run_steps(r, n_k[k - 2]);
    e.error = 2 * std::max(d_k[k - 2], d);
    return true;
  }
  if (k < 2 || !std::isfinite(d_k[k - 2])) return false;
  const double order = std::log2(d_k[k - 2] / d);
  if (!order_seen(order, p)) return false;  // not yet asymptotic
  // Asymptotic: the finer state x(n) has error ≈ d/(2^p - 1), and e ∝ n^-p.
  const double err_n = d / (std::pow(2.0, p) - 1);
  double n_star = std::ceil(n * std::pow(err_n / (kSafety * r.tolerance), 1.0 / p));
  n_star = std::max(n_star, n_k[k - 2]);  // do not extrapolate below the verified range
  e.usable = true;
  e.observed_order = order;
  e.config = fixed_config(e.method, r, n_star);
  e.steps = run_steps(r, n_star);
  e.error = err_n * std::pow(n / n_star, p);
  return true;
}

// Why a ladder that ran out of budget at n steps settled nothing.
std::string ladder_note(const std::vector<double>& d_k, int p, double n, double budget_s) {
  const double last = d_k.empty() ? 0 : d_k.back();
  return d_k.empty() ? "pilot budget (" + format_number(budget_s * 1e3, 2) + " ms) too small for a second run" :
         last <= kRoundOff ? "no change measured" :
         "order " + std::to_string(p) + " not seen within the pilot's budget (" + format_number(budget_s * 1e3, 2) +
         " ms: up to " + format_number(n, 0, 'f') + " steps; last difference " + format_number(last, 1, 'e') + ")";
}

MethodEstimate fixed_step_estimate(Method method, const RigidBodyModel& m, const BodyState& s0,
                                   const ChoiceRequest& r, double budget_s) {
  MethodEstimate e;
  e.method = method;
  const MethodInfo& info = method_info(method);
  const int p = info.closed_form_if_free ? 2 : info.order;  // closed form + kicks: Strang, order 2
  const double ns = step_cost_ns(method, m);
  std::vector<double> n_k, d_k;  // d_k[i] = error(x at n_k[i], x at n_k[i+1])
  std::optional<BodyState> prev = run(m, s0, fixed_config(method, r, 64), r.duration);
  double n = 64, spent = 64 * ns * 1e-9;
  n_k.push_back(n);
  while (2 * n <= kMaxPilotSteps && spent + 2 * n * ns * 1e-9 <= budget_s) {
    n *= 2;
    spent += n * ns * 1e-9;
    std::optional<BodyState> cur = run(m, s0, fixed_config(method, r, n), r.duration);
    n_k.push_back(n);
    d_k.push_back(prev && cur ? end_state_error(m, *prev, *cur) : std::numeric_limits<double>::infinity());
    prev = cur;
    if (ladder_settles(n_k, d_k, p, r, e)) break;
  }
  if (!e.usable) {
    e.note = ladder_note(d_k, p, n, budget_s);
    return e;
  }
  if (e.steps > kMaxRunSteps) {
    e.usable = false;
    e.note = "needs " + format_number(e.steps, 2) + " steps, beyond the cap of " + format_number(kMaxRunSteps);
    return e;
  }
  e.cost_s = e.steps * ns * 1e-9;
  return e;
}

// An adaptive pair needs no pilot ladder: its rtol asks for the end error
// (embedded_rk.hpp: the pairs deliver within ~10× of rtol on the bench
// problems), so it runs at rtol = tolerance / kAdaptiveMargin. `priced`: the
// first 1/kPriceWindows of the run at that rtol prices it: its steps there,
// then the rest of the run at the step its controller has settled on (the
// first steps are short: the starting step is a guess); otherwise steps and
// cost stay 0 (not measured).
MethodEstimate adaptive_estimate(Method method, const ChoiceRequest& r, bool priced, const RigidBodyModel& m,
                                 const BodyState& s0) {
  MethodEstimate e;
  e.method = method;
  e.config.method = method;
  e.config.dt = r.duration;
  e.config.rtol = r.tolerance / kAdaptiveMargin;
  e.config.atol = e.config.rtol;  // as the bench's sweep and proportionality chart run the pairs
  e.error = e.config.rtol;
  e.usable = true;
  if (!priced) return e;
  AdaptiveOptions o;
  o.rtol = e.config.rtol;
  o.atol = e.config.atol;
  try {
    const std::unique_ptr<AdaptiveIntegrator> pair = method_info(method).adaptive(m, s0, 0.0, o);
    pair->advance_to(r.duration / kPriceWindows);
    const double rest = std::max(0.0, r.duration - pair->time());
    e.steps = static_cast<double>(std::max(1L, pair->accepted())) + std::ceil(rest / pair->next_step());
  } catch (const Diverged&) {
    e.usable = false;
    e.note = "diverged in the first 1/" + format_number(kPriceWindows, 0, 'f') + " of the run";
    return e;
  }
  e.cost_s = e.steps * step_cost_ns(method, m) * 1e-9;
  return e;
}

// `exact` on a torqued body: the closed-form free rotation Strang-composed with
// the force kicks, order 2. A ladder over the whole run would cost more than
// its run, so the error is measured on the first 1/kProbeWindows of it, at 4,
// 8 and 16 steps there (Richardson: x16's error ≈ |x8 − x16| / 3 once the
// differences show order 2), and taken to grow at most linearly in time: a
// splitting's error on a near-integrable rotation is a bounded oscillation plus
// a linear drift (Hairer, Lubich & Wanner, "Geometric Numerical Integration",
// X.3), so extrapolating the window's error linearly bounds it. On the bench's
// torqued top this over-predicts the end error by 1.1× (scripts/adaptive_study.sh
// auto). Being a bound, it aims at kBoundSafety of the tolerance, not kSafety.
// Tried only where the probe costs at most a quarter of the pair's run; given
// up after two probes (order 2 assumed) when it would cost more than the pair.
MethodEstimate kicked_exact_estimate(Method method, const RigidBodyModel& m, const BodyState& s0,
                                     const ChoiceRequest& r, double pair_cost_s) {
  MethodEstimate e;
  e.method = method;
  const double ns = step_cost_ns(method, m), k = kProbeWindows, window = r.duration / k;
  if (4 * (4 + 8 + 16) * ns * 1e-9 > pair_cost_s) {
    e.note = "not tried: its probe would cost over a quarter of the pair's run";
    return e;
  }
  // The window in n steps, unguarded (a blow-up shows as a non-finite difference).
  auto at = [&](double n) { return integrate_fixed(method, m, s0, 0.0, window / n, static_cast<long>(n)); };
  // Steps over the run for an end error `err` at n steps to meet the tolerance (order 2).
  auto needed = [&](double err, double n) { return std::ceil(n * std::sqrt(err / (kBoundSafety * r.tolerance))); };
  const BodyState x4 = at(4), x8 = at(8);
  const double d1 = end_state_error(m, x4, x8);
  if (std::isfinite(d1) && needed(k * d1 / 3, 8 * k) * ns * 1e-9 > pair_cost_s) {
    e.note = "priced above the pair on the first two probes";
    return e;
  }
  const double d2 = end_state_error(m, x8, at(16));
  e.observed_order = std::log2(d1 / d2);
  if (!(d2 > kRoundOff) || !order_seen(e.observed_order, 2)) {  // NaN fails too
    e.note = "order 2 not seen on the first 1/" + format_number(k, 0, 'f') + " of the run (observed " +
             format_number(e.observed_order, 2) + ")";
    return e;
  }
  const double n16 = 16 * k, err16 = k * d2 / 3;  // over the run, at n16 steps
  const double n_star = std::max(8 * k, needed(err16, n16));
  e.usable = true;
  e.config.method = method;
  e.config.dt = r.duration / n_star;
  e.steps = run_steps(r, n_star);
  e.error = err16 * std::pow(n16 / n_star, 2);
  e.cost_s = e.steps * ns * 1e-9;
  return e;
}

}  // namespace

double end_state_error(const RigidBodyModel& m, const BodyState& a, const BodyState& b) {
  const double gyration = std::sqrt(m.inertia.sum() / (2 * m.mass));
  const double shift = (a.c - b.c).norm();
  return std::max(rotation_angle_between(a.q, b.q), gyration > 0 ? shift / gyration : shift);
}

double step_cost_ns(Method method, const RigidBodyModel& m) {
  const StepCost& c = method_info(method).cost;
  if (m.forces.empty()) return c.free;
  return closed_form_is_trigonometric(m.inertia) ? c.forced_axisymmetric : c.forced;
}

bool auto_takes_closed_form(const RigidBodyModel& m) { return m.forces.empty(); }

MethodChoice auto_without_tolerance(const RigidBodyModel& m, const StepConfig& asked) {
  MethodChoice c;
  c.config = asked;
  if (auto_takes_closed_form(m)) c.config.method = Method::exact;
  c.reason = std::string(method_name(c.config.method)) +
             (auto_takes_closed_form(m) ? ": torque-free, closed form" : ": has forces (no tolerance given)");
  return c;
}

namespace {

// Candidates (MethodInfo::auto_candidate): the methods whose error stays
// bounded over long runs, plus rk4 and the adaptive pairs (users' usual
// picks). The first-order methods are left out: wherever they would be
// cheapest, splitting costs about the same and keeps |L| exactly.
// With `prune` (scenes): `exact` when no force torques the body and its
// ladder qualifies (the rotation is then the closed form: it agrees at
// round-off at once); otherwise the highest-order adaptive pair, unpriced
// and with no pilot at all (pilot ladders cost 2–10 runs), except on a
// torqued axisymmetric body, where it is priced and weighed against `exact`
// with kicks (kicked_exact_estimate). On every bench problem auto's whole
// cost stays within 1.8× of the cheapest configuration meeting tolerances
// 1e-3…1e-8, timed alike (`tumble bench`, auto.csv).
// Without `prune`, every candidate is measured (tests, `tumble info`-like uses).
std::vector<MethodEstimate> estimate_candidates(const RigidBodyModel& m, const BodyState& s0, const ChoiceRequest& r) {
  std::vector<MethodEstimate> out;
  if (!r.prune) {
    for (const MethodInfo& info : method_table()) {
      if (!info.auto_candidate) continue;
      out.push_back(info.adaptive ? adaptive_estimate(info.method, r, true, m, s0)
                                  : fixed_step_estimate(info.method, m, s0, r, kPilotBudgetS));
    }
    return out;
  }
  for (const MethodInfo& info : method_table())
    if (info.auto_candidate && info.closed_form_if_free && !m.forces.has_torque()) {
      MethodEstimate e = fixed_step_estimate(info.method, m, s0, r, kPilotBudgetS);
      if (e.usable) out.push_back(std::move(e));
    }
  const MethodInfo* pair = nullptr;
  for (const MethodInfo& info : method_table())
    if (info.auto_candidate && info.adaptive && (!pair || info.order > pair->order)) pair = &info;
  // On a torqued body `exact` (order 2) can beat the pair (order 8) only
  // where its step costs far less: the trigonometric closed form of an
  // axisymmetric body, not the elliptic one (method_costs.inc). Only then is
  // the pair priced, to weigh the two.
  const MethodInfo* kicked = nullptr;
  for (const MethodInfo& info : method_table())
    if (pair && m.forces.has_torque() && info.auto_candidate && info.closed_form_if_free &&
        4 * step_cost_ns(info.method, m) <= step_cost_ns(pair->method, m))
      kicked = &info;
  if (out.empty() && pair) {
    out.push_back(adaptive_estimate(pair->method, r, kicked != nullptr, m, s0));
    if (kicked && out[0].usable) out.push_back(kicked_exact_estimate(kicked->method, m, s0, r, out[0].cost_s));
  }
  return out;
}

// "dop853 at rtol 1e-09: predicted end error ... ; next cheapest ...".
std::string choice_reason(const MethodEstimate& best, const MethodEstimate* runner, const ChoiceRequest& r) {
  std::string reason =
      std::string(method_name(best.method)) +
      (method_info(best.method).adaptive ? " at rtol " + format_number(best.config.rtol, 0, 'e')
                                         : " at dt " + format_number(best.config.dt, 3) + " s") +
      ": predicted end error " + format_number(best.error, 1, 'e') + " rad <= tolerance " + format_number(r.tolerance, 3) +
      (best.steps > 0 ? ", " + format_number(best.steps, 0, 'f') + " steps, ~" + format_number(best.cost_s * 1e3, 2) + " ms"
                      : " (its rtol asks for the end error; no pilot)");
  if (runner)
    reason += "; next cheapest " + std::string(method_name(runner->method)) + " ~" +
              format_number(runner->cost_s * 1e3, 2) + " ms";
  return reason;
}

}  // namespace

MethodChoice choose_method(const RigidBodyModel& m, const BodyState& s0, const ChoiceRequest& r) {
  MethodChoice c;
  if (auto_takes_closed_form(m)) {
    c.config.method = Method::exact;
    c.config.dt = r.duration;
    c.reason = "exact: torque-free, so the closed form (error at round-off)";
    return c;
  }
  c.candidates = estimate_candidates(m, s0, r);
  const MethodEstimate* best = nullptr;
  for (const MethodEstimate& e : c.candidates)
    if (e.usable && (!best || e.cost_s < best->cost_s)) best = &e;
  if (!best) {
    std::string why;
    for (const MethodEstimate& e : c.candidates) why += std::string(why.empty() ? "" : "; ") + std::string(method_name(e.method)) + ": " + e.note;
    throw InputError("method = \"auto\": no method could be shown to meet tolerance " + format_number(r.tolerance, 3) +
                     " rad on body '" + m.name + "' (" + why + "); pick a method and dt yourself");
  }
  c.config = best->config;
  c.error = best->error;
  c.cost_s = best->cost_s;
  const MethodEstimate* runner = nullptr;
  for (const MethodEstimate& e : c.candidates)
    if (e.usable && &e != best && (!runner || e.cost_s < runner->cost_s)) runner = &e;
  c.reason = choice_reason(*best, runner, r);
  return c;
}

}  // namespace tumble
