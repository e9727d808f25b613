// Peer dispatch: which engines were compiled in, their settings, and their
// work-precision points; tumble's methods and the peers as Steppers.
#include "bench/peers.hpp"

#include <boost/version.hpp>
#include <cmath>

#include "core/fixed_stepper.hpp"

namespace tumble::bench {

namespace {

class MethodStepper final : public Stepper {
 public:
  MethodStepper(Method method, const RigidBodyModel& m, const BodyState& s0) : s_(method, m, s0) {}
  void step(double h) override {
    s_.step(t_, h);
    t_ += h;
  }
  BodyState state() const override { return s_.state(); }

 private:
  FixedStepper s_;  // as a run steps: rk4 carries Euler's coordinates
  double t_ = 0;
};

}  // namespace

std::unique_ptr<Stepper> method_stepper(Method method, const RigidBodyModel& m, const BodyState& s0) {
  return std::make_unique<MethodStepper>(method, m, s0);
}

BodyState run_stepper(const MakeStepper& make, const RigidBodyModel& m, const BodyState& s0, double T, double dt) {
  const long n = std::max(1L, std::lround(T / dt));
  const double h = T / static_cast<double>(n);
  const std::unique_ptr<Stepper> s = make(m, s0);
  for (long i = 0; i < n; ++i) s->step(h);
  return s->state();
}

PeerConfig stepped_peer(std::string label, MakeStepper make) {
  auto run = [make](const RigidBodyModel& m, const BodyState& s0, double T, double dt) {
    return run_stepper(make, m, s0, T, dt);
  };
  return {std::move(label), "dt", run, std::move(make)};
}

std::vector<PeerConfig> peer_configs() {
  std::vector<PeerConfig> v = odeint_configs();
#if TUMBLE_HAVE_BULLET
  for (PeerConfig& c : bullet_configs()) v.push_back(std::move(c));
#endif
#if TUMBLE_HAVE_ODE
  for (PeerConfig& c : ode_configs()) v.push_back(std::move(c));
#endif
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
  v.push_back("Boost.odeint " BOOST_LIB_VERSION " (header-only, libboost-dev)");
#if TUMBLE_HAVE_BULLET
  v.push_back("Bullet " TUMBLE_BULLET_VERSION " (double precision, libbullet-dev)");
#endif
#if TUMBLE_HAVE_ODE
  v.push_back("ODE " TUMBLE_ODE_VERSION " (double precision, libode-dev)");
#endif
  return v;
}

std::string peer_settings_markdown() {
  std::string s =
      "- Boost.odeint: state std::array<double, 7>, default algebra. `odeint_rk4_world`: runge_kutta4 on the seed's "
      "(q, L_world) with q normalised inside f; `odeint_rk4_body`: runge_kutta4 on (q, Π = Rᵀ L), Euler's equations "
      "Π' = Π × ω_body and q' = ½ q ⊗ ω_body; `odeint_dopri5_body`: make_controlled(atol = rtol, rtol, "
      "runge_kutta_dopri5) with integrate_adaptive on the body formulation (on the stability map and flip charts: "
      "its fixed-step Dormand–Prince step). The reported q is normalised once at the end.\n";
#if TUMBLE_HAVE_BULLET
  s += "- Bullet: one btRigidBody (mass, local inertia = principal moments, btSphereShape 0.1 m, no damping, "
       "deactivation disabled) in a btDiscreteDynamicsWorld (dbvt broadphase, sequential-impulse solver), gravity 0, "
       "stepSimulation(dt, 0) (one internal step of exactly dt). Rigid-body flags: `bullet_none` 0 (no gyroscopic "
       "term: ω constant), `bullet_explicit` BT_ENABLE_GYROSCOPIC_FORCE_EXPLICIT (the world's default "
       "max gyroscopic force clamp), `bullet_implicit_body` BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY "
       "(Bullet's default), `bullet_implicit_world` BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_WORLD.\n";
#endif
#if TUMBLE_HAVE_ODE
  s += "- ODE: one dBody (dMassSetParameters with the principal moments), gravity 0, no joints, dWorldStep(dt), "
       "auto-disable off. `ode_default`: as created (gyroscopic mode on, finite rotation off); `ode_gyro_off`: "
       "dBodySetGyroscopicMode(0); `ode_finite_rotation`: gyroscopic on + dBodySetFiniteRotationMode(1) with no axis "
       "(full finite-rotation update).\n";
#else
  s += "- ODE: not found (install libode-dev and re-run CMake)\n";
#endif
#if !TUMBLE_HAVE_BULLET
  s += "- Bullet: not found (install libbullet-dev and re-run CMake)\n";
#endif
  s += "- Peers run on torque-free problems only. Bullet and ODE CPU time covers creating the world and body and all "
       "steps of one run.\n";
  return s;
}

std::vector<WpRow> peer_work_precision(const Problem& p, const Settings& st, std::ostream& log) {
  std::vector<WpRow> rows;
  for (const PeerConfig& c : peer_configs()) {
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
