#include "bench/problems.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <sstream>

#include "core/dynamics.hpp"
#include "core/fixed_stepper.hpp"
#include "core/methods/free_rotation_exact.hpp"
#include "core/quaternion.hpp"
#include "core/methods/embedded_rk.hpp"

namespace tumble::bench {

RigidBodyModel diagonal_model(const std::string& name, const Eigen::Vector3d& I, const ForceSet& f) {
  RigidBodyModel m;
  m.name = name;
  m.mass = 1;
  m.inertia = I;
  m.inv_inertia = I.cwiseInverse();
  m.forces = f;
  return m;
}

BodyState spinning_state(const RigidBodyModel& m, const Eigen::Vector3d& omega_body) {
  InitialConditions ic;
  ic.omega = omega_body;
  return make_state(m, ic);
}

Problem t_handle_problem() {
  Problem p;
  p.name = "t_handle";
  p.description = "T-handle: moments (1, 2, 3) kg m^2, omega_body (0.01, 10, 0.01) rad/s, 10 s, torque-free "
                  "(4 Dzhanibekov flips); reference: closed form";
  p.model = diagonal_model("t_handle", {1, 2, 3});
  p.s0 = spinning_state(p.model, {0.01, 10, 0.01});
  p.reference = exact_free_state(p.model, p.s0, p.duration);
  p.peers = true;
  return p;
}

Problem symmetric_top_problem() {
  Problem p;
  p.name = "symmetric_top";
  p.description = "symmetric top: moments (2, 2, 4) kg m^2, omega_body (3, 1, 5) rad/s, 10 s, torque-free; "
                  "reference: closed form";
  p.model = diagonal_model("symmetric_top", {2, 2, 4});
  p.s0 = spinning_state(p.model, {3, 1, 5});
  p.reference = exact_free_state(p.model, p.s0, p.duration);
  return p;
}

Problem forced_problem() {
  Problem p;
  p.name = "forced";
  p.description = "forced T-handle: moments (1, 2, 3) kg m^2, 1 kg, omega_body (0.01, 10, 0.01) rad/s, gravity "
                  "(0, 0, -9.81) m/s^2 plus a body-fixed force (0, 0, 2) N at (1, 0, 0) m, 10 s; reference: "
                  "dop853 at rtol 1e-13";
  ForceSet f;
  f.terms.push_back(UniformGravity{Eigen::Vector3d(0, 0, -9.81)});
  f.terms.push_back(PointForce{Eigen::Vector3d(0, 0, 2), Eigen::Vector3d(1, 0, 0), Frame::body});
  p.model = diagonal_model("forced", {1, 2, 3}, f);
  p.s0 = spinning_state(p.model, {0.01, 10, 0.01});
  p.torque_free = false;
  p.peers = true;
  p.reference = reference_run(p.model, p.s0, p.duration);
  // The same reference integrator on the torque-free T-handle, against the closed form.
  const Problem th = t_handle_problem();
  p.reference_check = rotation_angle_between(reference_run(th.model, th.s0, th.duration).q, th.reference.q);
  return p;
}

namespace {

// A forced scene: its reference is reference_run; odeint joins the peers.
Problem forced_scene(std::string name, std::string description, RigidBodyModel m, const Eigen::Vector3d& omega_body) {
  Problem p;
  p.name = std::move(name);
  p.description = std::move(description) + "; reference: dop853 at rtol 1e-13";
  p.model = std::move(m);
  p.s0 = spinning_state(p.model, omega_body);
  p.torque_free = false;
  p.peers = true;
  p.reference = reference_run(p.model, p.s0, p.duration);
  return p;
}

}  // namespace

std::vector<Problem> scene_problems() {
  ForceSet thruster, damped, top;
  thruster.terms.push_back(UniformGravity{Eigen::Vector3d(0, 0, -9.81)});
  thruster.terms.push_back(PointForce{Eigen::Vector3d(0, 0, 2), Eigen::Vector3d(1, 0, 0), Frame::body});
  thruster.terms.push_back(ConstantTorque{Eigen::Vector3d(0, 0.3, 0), Frame::body});
  damped.terms.push_back(UniformGravity{Eigen::Vector3d(0, 0, -9.81)});
  damped.terms.push_back(LinearDamping{0.3});
  damped.terms.push_back(AngularDamping{0.05});
  top.terms.push_back(ConstantTorque{Eigen::Vector3d(0.5, 0, 0), Frame::world});
  top.terms.push_back(AngularDamping{0.02});
  return {forced_scene("thruster",
                       "thruster: moments (1, 2, 3) kg m^2, 1 kg, omega_body (0.5, 3, 0.2) rad/s, gravity, body-fixed 2 N "
                       "along z at (1, 0, 0) m, body torque (0, 0.3, 0) N m, 10 s",
                       diagonal_model("thruster", {1, 2, 3}, thruster), {0.5, 3, 0.2}),
          forced_scene("damped",
                       "damped tumbler: moments (1, 2, 3) kg m^2, 1 kg, omega_body (0.3, 6, 0.2) rad/s, gravity, linear "
                       "damping 0.3 N s/m, angular damping 0.05 N m s, 10 s",
                       diagonal_model("damped", {1, 2, 3}, damped), {0.3, 6, 0.2}),
          forced_scene("torqued_top",
                       "torqued top: moments (2, 2, 4) kg m^2, 1 kg, omega_body (3, 1, 5) rad/s, world torque (0.5, 0, 0) "
                       "N m, angular damping 0.02 N m s, 10 s",
                       diagonal_model("torqued_top", {2, 2, 4}, top), {3, 1, 5})};
}

std::vector<Problem> all_problems() {
  std::vector<Problem> v = {t_handle_problem(), symmetric_top_problem(), forced_problem()};
  for (Problem& p : scene_problems()) v.push_back(std::move(p));
  return v;
}

Problem body_problem(const std::string& name, const RigidBodyModel& m, const BodyState& s0, double duration) {
  Problem p;
  p.name = name;
  p.model = m;
  p.s0 = s0;
  p.duration = duration;
  p.torque_free = m.forces.empty();
  p.peers = true;  // forced bodies: the peers that take forces (odeint)
  p.reference = p.torque_free ? exact_free_state(m, s0, duration) : reference_run(m, s0, duration);
  // Largest step h·|ω| = 1 at the start, and at least 10 steps per run.
  const double w = omega_principal(m, s0).norm();
  p.dt_max = std::min(w > 0 ? 1 / w : duration, duration / 10);
  std::ostringstream d;
  d.precision(4);
  d << "body `" << m.name << "`: mass " << m.mass << " kg, principal moments (" << m.inertia.x() << ", "
    << m.inertia.y() << ", " << m.inertia.z() << ") kg m^2, |omega| " << w << " rad/s at t = 0, " << duration << " s, "
    << (p.torque_free ? "torque-free; reference: closed form" : "forced; reference: dop853 at rtol 1e-13");
  p.description = d.str();
  return p;
}

Errors errors(const Problem& p, const BodyState& s) {
  Errors e;
  if (!s.all_finite()) return {NAN, NAN};
  e.angle = rotation_angle_between(s.q, p.reference.q);
  const double eref = total_energy(p.model, p.reference);
  // A potential can make E_ref ~ 0 (a body falling through c = 0): scale by the kinetic energy then.
  const double scale = std::max(std::abs(eref), kinetic_energy(p.model, p.reference));
  e.energy = std::abs(total_energy(p.model, s) - eref) / scale;
  return e;
}

BodyState run_fixed(Method method, const RigidBodyModel& m, const BodyState& s0, double T, double dt) {
  const long n = std::max(1L, std::lround(T / dt));
  const double h = T / static_cast<double>(n);
  // As a run steps (FixedStepper: rk4 carries Euler's coordinates), in blocks
  // of 1024 steps so a blow-up stops early.
  FixedStepper s(method, m, s0);
  for (long i = 0; i < n; ++i) {
    s.step(static_cast<double>(i) * h, h);
    if ((i & 1023) == 0 && !s.state().all_finite()) break;
  }
  return s.state();
}

BodyState run_adaptive(Method method, const RigidBodyModel& m, const BodyState& s0, double T, double rtol) {
  AdaptiveOptions o;
  o.rtol = rtol;
  o.atol = rtol;
  o.t_stop = T;
  return method_info(method).adaptive(m, s0, 0.0, o)->advance_to(T);
}

BodyState reference_run(const RigidBodyModel& m, const BodyState& s0, double T) {
  return run_adaptive(Method::dop853, m, s0, T, kReferenceRtol);
}

double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

double median_cpu_seconds(const std::function<void()>& fn, double min_batch_s, int repeats) {
  std::vector<double> per_call;
  long batch = 1;
  for (int r = 0; r < repeats; ++r) {
    double elapsed = 0;
    while (true) {
      const double t0 = thread_cpu_seconds();
      for (long i = 0; i < batch; ++i) fn();
      elapsed = thread_cpu_seconds() - t0;
      if (elapsed >= min_batch_s) break;
      // Grow the batch toward the target span (at most ×10 per try).
      const double want = elapsed > 0 ? 1.2 * min_batch_s / elapsed : 10.0;
      batch = std::max(batch + 1, static_cast<long>(static_cast<double>(batch) * std::min(want, 10.0)));
    }
    per_call.push_back(elapsed / static_cast<double>(batch));
  }
  std::sort(per_call.begin(), per_call.end());
  return per_call[per_call.size() / 2];
}

std::vector<double> log_sweep(double hi, double lo, int per_decade) {
  std::vector<double> v;
  const int n = static_cast<int>(std::lround(std::log10(hi / lo) * per_decade));
  for (int i = 0; i <= n; ++i) v.push_back(hi * std::pow(10.0, -static_cast<double>(i) / per_decade));
  return v;
}

std::vector<double> decade_grid(double hi, double lo, int per_decade) {
  std::vector<double> v;
  const double pd = per_decade;
  const long top = std::lround(std::floor(std::log10(hi) * pd + 1e-9));
  const long bottom = std::lround(std::ceil(std::log10(lo) * pd - 1e-9));
  for (long k = top; k >= bottom; --k) v.push_back(std::pow(10.0, static_cast<double>(k) / pd));
  return v;
}

void FlipCounter::observe(double pi2, double t) {
  const double sign = pi2 > 0 ? 1.0 : (pi2 < 0 ? -1.0 : 0.0);
  if (sign == 0) return;
  if (last_sign != 0 && sign != last_sign) {
    ++count;
    if (first_time < 0) first_time = t;
  }
  last_sign = sign;
}

}  // namespace tumble::bench
