#include "core/propagator.hpp"

#include <cmath>
#include <string>

#include "base/format.hpp"
#include "core/dynamics.hpp"
#include "core/error.hpp"
#include "core/quaternion.hpp"

namespace tumble {

namespace {

// Energy above E0 + driving work by more than this many times the energy scale
// (|E0| parts plus the work that flowed) means the method blew up. The old
// torque-free rule was ×10; a blow-up grows geometrically, so it passes any
// fixed factor within a few steps, while a method that follows the motion
// stays within round-off or its (small) truncation error.
constexpr double kBlowUp = 10;

// Largest rate (1/s) at which the state turns or decays: |ω| plus the damping rates.
double rate(const RigidBodyModel& m, const BodyState& s) {
  return omega_world(m, s).norm() + damping_rate(m);
}

}  // namespace

std::optional<std::string> coarse_step_warning(const RigidBodyModel& m, const BodyState& s0, const StepConfig& cfg) {
  const MethodInfo& info = method_info(cfg.method);
  if (info.adaptive || (info.closed_form_if_free && m.forces.empty())) return std::nullopt;
  const double turn = cfg.dt * rate(m, s0);
  if (!(turn > info.max_turn_per_step)) return std::nullopt;  // NaN too: no NaN in a message
  return "body '" + m.name + "': dt = " + format_number(cfg.dt, 3) + " s turns or damps by " + format_number(turn, 3) +
         " rad per step, beyond the " + format_number(info.max_turn_per_step, 3) + " that " + std::string(info.name) +
         " follows; expect a wrong or diverging run (dt <= " + format_number(info.max_turn_per_step / rate(m, s0), 3) +
         " s follows it)";
}

Propagator::Propagator(const RigidBodyModel& m, const BodyState& s0, const StepConfig& cfg)
    : m_(&m), info_(&method_info(cfg.method)), cfg_(cfg), s0_(s0), s_(s0), grid_(cfg.method, m, s0), e0_(total_energy(m, s0)) {
  scale0_ = kinetic_energy(m, s0) + std::abs(potential_energy(m, s0));
  erot0_ = rotational_energy(m, momentum_body(s0));
  const EnergyFlow f = energy_flow(m, s0);
  power_ = f.driving;
  power_abs_ = f.scale;
  if (info_->closed_form_if_free && m.forces.empty()) exact_.emplace(m.inertia, s0.q, s0.L);
  if (info_->adaptive) {
    AdaptiveOptions o;
    o.rtol = cfg_.rtol;
    o.atol = cfg_.atol;
    adaptive_ = info_->adaptive(m, s0, 0.0, o);
  }
}

void Propagator::check(const BodyState& s, double t, double h) {
  // A quaternion whose norm overflowed normalises to 0 yet stays finite.
  bool bad = !s.all_finite() || std::abs(s.q.squaredNorm() - 1.0) > 1e-6;
  if (!bad) {
    // Energy balance: E − E0 can exceed the work W of the driving
    // terms (trapezoidal in the step's end powers) only by the method's error;
    // damping can only remove energy. Torque-free: W = 0, E is an invariant.
    const EnergyFlow f = energy_flow(*m_, s);
    work_ += 0.5 * h * (power_ + f.driving);
    work_abs_ += 0.5 * std::abs(h) * (power_abs_ + f.scale);
    power_ = f.driving;
    power_abs_ = f.scale;
    const double e = total_energy(*m_, s);
    bad = !std::isfinite(e) || e - e0_ - work_ > kBlowUp * (scale0_ + work_abs_) + 1e-300;
  }
  if (!bad) return;
  diverged(s.all_finite(), t, h);
}

bool Propagator::free_energy_held(double erot) const {
  return erot - erot0_ <= kBlowUp * scale0_ + 1e-300;  // NaN fails
}

void Propagator::check_free(const BodyCoords& x, double t, double h) {
  const double erot = rotational_energy(*m_, x.pi);  // J
  // NaN or ±inf if any coordinate is (a sum of finite ones overflows only far beyond any real run).
  const double all = (x.c.sum() + x.P.sum()) + (x.q.coeffs().sum() + erot);
  if (free_energy_held(erot) && std::isfinite(all)) return;
  diverged(std::isfinite(all), t, h);
}

void Propagator::check_free(const BodyState& s, double t, double h) {
  const double erot = rotational_energy(*m_, momentum_body(s));  // J
  const double all = (s.c.sum() + s.P.sum()) + (s.L.sum() + erot);
  if (free_energy_held(erot) && std::abs(s.q.squaredNorm() - 1.0) <= 1e-6 && std::isfinite(all)) return;
  diverged(std::isfinite(all) && s.q.coeffs().allFinite(), t, h);
}

void Propagator::diverged(bool finite, double t, double h) const {
  std::string msg = "diverged at t=" + format_number(t, 6) + " s, step " + std::to_string(steps_) + ", body '" +
                    m_->name + "', method " + std::string(info_->name) +
                    (finite ? " (energy grew beyond the work of the declared forces)" : "");
  const bool geometric = info_->geometric;
  if (std::isfinite(h) && h > 0)
    msg += "; try dt <= " + format_number(h / 10, 6) + " s" + (geometric ? "" : " or a geometric method (splitting, exact)");
  else if (!geometric)
    msg += "; try a geometric method (splitting, exact)";
  throw Diverged(msg, t, steps_);
}

void Propagator::grid_step() {
  grid_.step(static_cast<double>(steps_) * cfg_.dt, cfg_.dt);
  ++steps_;
  const double t = static_cast<double>(steps_) * cfg_.dt;
  if (!m_->forces.empty()) return check(grid_.state(), t, cfg_.dt);
  if (const BodyCoords* x = grid_.coords()) return check_free(*x, t, cfg_.dt);
  check_free(grid_.seed_state(), t, cfg_.dt);
}

const BodyState& Propagator::advance_to(double t) {
  if (t <= t_) return s_;
  const Eigen::Quaterniond prev = s_.q;
  if (exact_) {
    s_ = s0_;
    s_.c = s0_.c + t * s0_.P / m_->mass;
    s_.q = same_hemisphere(exact_->orientation(t), prev);
    const double h = t - t_;
    t_ = t;
    ++steps_;
    check_free(s_, t, h);  // torque-free: E is the invariant; no force terms to sum
    return s_;
  }
  if (adaptive_) {
    try {
      s_ = adaptive_->advance_to(t);
    } catch (const Diverged&) {
      t_ = t;
      check(s_, t, cfg_.dt);
      throw;
    }
    s_.q = same_hemisphere(s_.q, prev);
    steps_ = adaptive_->accepted();
    check(s_, t, t - t_);
    t_ = t;
    return s_;
  }
  // Grid points up to t; a t within round-off of one is that point.
  const double k = t / cfg_.dt;
  const double nearest = std::round(k);
  const bool on_grid = std::abs(k - nearest) <= 1e-9 * std::max(1.0, k);
  const long last = on_grid ? static_cast<long>(nearest) : static_cast<long>(std::floor(k));
  while (steps_ < last) grid_step();
  if (on_grid) {
    s_ = grid_.state();
  } else {
    // Dense output by a partial step from the grid state; the grid goes on from grid_.
    const double tn = static_cast<double>(steps_) * cfg_.dt;
    s_ = grid_.peek(tn, t - tn);
    if (!s_.all_finite()) check(s_, t, t - tn);
  }
  t_ = t;
  return s_;
}

const BodyState& Propagator::advance_steps(long n) {
  if (exact_ || adaptive_) return advance_to(t_ + static_cast<double>(n) * cfg_.dt);
  const long target = steps_ + n;
  while (steps_ < target) grid_step();
  s_ = grid_.state();
  t_ = static_cast<double>(steps_) * cfg_.dt;
  return s_;
}

}  // namespace tumble
