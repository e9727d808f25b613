#include "core/propagator.hpp"

#include <cmath>
#include <sstream>

#include "core/dynamics.hpp"
#include "core/error.hpp"
#include "core/quaternion.hpp"

namespace tumble {

Propagator::Propagator(const RigidBodyModel& m, const BodyState& s0, const StepConfig& cfg)
    : m_(&m), cfg_(cfg), s0_(s0), s_(s0), e0_(total_energy(m, s0)), torque_free_(m.forces.empty()) {
  if (cfg_.method == Method::exact && torque_free_) exact_.emplace(m.inertia, s0.q, s0.L);
  if (cfg_.method == Method::rk45) {
    Rk45Options o;
    o.rtol = cfg_.rtol;
    o.atol = cfg_.atol;
    rk45_ = std::make_unique<Rk45>(m, s0, 0.0, o);
  }
}

void Propagator::check(double h) {
  // A quaternion whose norm overflowed normalises to 0 yet stays finite.
  bool bad = !s_.all_finite() || std::abs(s_.q.squaredNorm() - 1.0) > 1e-6;
  // Torque-free: kinetic energy is an invariant; ×10 growth means the method blew up.
  if (!bad && torque_free_) {
    const double e = total_energy(*m_, s_);
    bad = !std::isfinite(e) || std::abs(e) > 10 * std::abs(e0_) + 1e-300;
  }
  if (!bad) return;
  std::ostringstream msg;
  msg.precision(6);
  msg << "diverged at t=" << t_ << " s, step " << steps_ << ", body '" << m_->name << "', method "
      << method_name(cfg_.method) << "; try dt <= " << h / 10 << " s or a geometric method (splitting, exact)";
  throw Diverged(msg.str(), t_, steps_);
}

void Propagator::do_step(double h) {
  const Eigen::Quaterniond prev = s_.q;
  s_ = step(cfg_.method, *m_, s_, t_, h);
  s_.q = same_hemisphere(s_.q, prev);
  t_ += h;
  ++steps_;
  check(h);
}

const BodyState& Propagator::advance_to(double t) {
  if (t <= t_) return s_;
  if (exact_) {
    const double h = t - t_;
    const Eigen::Quaterniond prev = s_.q;
    s_ = s0_;
    s_.c = s0_.c + t * s0_.P / m_->mass;
    s_.q = same_hemisphere(exact_->orientation(t), prev);
    t_ = t;
    ++steps_;
    check(h);
    return s_;
  }
  if (rk45_) {
    const Eigen::Quaterniond prev = s_.q;
    try {
      s_ = rk45_->advance_to(t);
    } catch (const Diverged&) {
      t_ = t;
      check(cfg_.dt);
      throw;
    }
    s_.q = same_hemisphere(s_.q, prev);
    t_ = t;
    steps_ = rk45_->accepted();
    check(cfg_.dt);
    return s_;
  }
  const double span = t - t_;
  const long n = std::max(1L, static_cast<long>(std::ceil(span / cfg_.dt * (1 - 1e-12))));
  const double h = span / static_cast<double>(n);
  const double t_end = t;
  for (long i = 0; i < n; ++i) do_step(h);
  t_ = t_end;  // no drift from summing h
  return s_;
}

const BodyState& Propagator::advance_steps(long n) {
  if (exact_ || rk45_) return advance_to(t_ + static_cast<double>(n) * cfg_.dt);
  for (long i = 0; i < n; ++i) do_step(cfg_.dt);
  return s_;
}

}  // namespace tumble
