// Peer dispatch: which engines were compiled in, their settings, and their
// work-precision points on the T-handle.
#include "bench/peers.hpp"

#include <cmath>

namespace tumble::bench {

std::vector<std::string> peers_found() {
  std::vector<std::string> v;
#if TUMBLE_HAVE_BULLET
  v.push_back("Bullet " TUMBLE_BULLET_VERSION " (double precision, libbullet-dev)");
#endif
#if TUMBLE_HAVE_ODE
  v.push_back("ODE " TUMBLE_ODE_VERSION " (double precision, libode-dev)");
#endif
  return v;
}

std::string peer_settings_markdown() {
  std::string s;
#if TUMBLE_HAVE_BULLET
  s += "- Bullet: one btRigidBody (mass 1 kg, local inertia (1, 2, 3) kg m^2, btSphereShape 0.1 m, no damping, "
       "deactivation disabled) in a btDiscreteDynamicsWorld (dbvt broadphase, sequential-impulse solver), gravity 0, "
       "stepSimulation(dt, 0) (one internal step of exactly dt). Rigid-body flags: `bullet_none` 0 (no gyroscopic "
       "term: ω constant), `bullet_explicit` BT_ENABLE_GYROSCOPIC_FORCE_EXPLICIT (the world's default "
       "max gyroscopic force clamp), `bullet_implicit_body` BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY "
       "(Bullet's default), `bullet_implicit_world` BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_WORLD.\n";
#endif
#if TUMBLE_HAVE_ODE
  s += "- ODE: one dBody (dMassSetParameters mass 1 kg, I = diag(1, 2, 3) kg m^2), gravity 0, no joints, dWorldStep(dt), "
       "auto-disable off. `ode_default`: as created (gyroscopic mode on, finite rotation off); `ode_gyro_off`: "
       "dBodySetGyroscopicMode(0); `ode_finite_rotation`: gyroscopic on + dBodySetFiniteRotationMode(1) with no axis "
       "(full finite-rotation update).\n";
#endif
  if (s.empty()) s = "- none found (install libbullet-dev / libode-dev and re-run CMake)\n";
  s += "- Peer CPU time covers creating the world and body and all steps of one 10 s run.\n";
  return s;
}

std::vector<WpRow> peer_work_precision(const Problem& p, const Settings& st, std::ostream& log) {
  std::vector<WpRow> rows;
  struct Engine {
    std::vector<std::string> labels;
    BodyState (*run)(const std::string&, const Problem&, double);
  };
  std::vector<Engine> engines;
#if TUMBLE_HAVE_BULLET
  engines.push_back({bullet_labels(), bullet_run});
#endif
#if TUMBLE_HAVE_ODE
  engines.push_back({ode_labels(), ode_run});
#endif
  const std::vector<double> dts = log_sweep(0.1, st.quick ? 1e-3 : 1e-5, st.quick ? 2 : 3);
  for (const Engine& e : engines)
    for (const std::string& label : e.labels) {
      for (double dt : dts) {
        BodyState s;
        auto once = [&] { s = e.run(label, p, dt); };
        once();
        const Errors err = errors(p, s);
        const double cpu = std::isfinite(err.angle) ? median_cpu_seconds(once, st.min_batch_s, st.repeats) : NAN;
        rows.push_back({p.name, label, "dt", dt, cpu, err.angle, err.energy});
      }
      log << "  work-precision " << p.name << " " << label << ": " << dts.size() << " points\n";
    }
  return rows;
}

}  // namespace tumble::bench
