// ODE peer: the body as one dBody stepped by dWorldStep.
#include "bench/peers/peer.hpp"

#if TUMBLE_HAVE_ODE
#include <ode/ode.h>

#include <memory>

namespace tumble::bench {

namespace {

enum class OdeMode { standard, gyro_off, finite_rotation };

class OdeStepper final : public Stepper {
 public:
  OdeStepper(OdeMode mode, const RigidBodyModel& m, const BodyState& s0) : m_(m), s0_(s0) {
    dInitODE2(0);  // reference counted; paired with dCloseODE in the destructor
    world_ = dWorldCreate();
    dWorldSetGravity(world_, 0, 0, 0);
    body_ = dBodyCreate(world_);
    dMass mass;
    const Eigen::Vector3d& I = m.inertia;
    dMassSetParameters(&mass, m.mass, 0, 0, 0, I.x(), I.y(), I.z(), 0, 0, 0);
    dBodySetMass(body_, &mass);
    const Eigen::Quaterniond& q0 = s0.q;
    const dQuaternion qd = {q0.w(), q0.x(), q0.y(), q0.z()};
    dBodySetQuaternion(body_, qd);
    dBodySetPosition(body_, s0.c.x(), s0.c.y(), s0.c.z());
    const Eigen::Vector3d w = s0.q * m.inv_inertia.cwiseProduct(s0.q.conjugate() * s0.L);
    dBodySetAngularVel(body_, w.x(), w.y(), w.z());
    const Eigen::Vector3d v = s0.P / m.mass;
    dBodySetLinearVel(body_, v.x(), v.y(), v.z());
    dBodySetAutoDisableFlag(body_, 0);
    if (mode == OdeMode::gyro_off) dBodySetGyroscopicMode(body_, 0);
    if (mode == OdeMode::finite_rotation) dBodySetFiniteRotationMode(body_, 1);
  }
  ~OdeStepper() override {
    dWorldDestroy(world_);
    dCloseODE();
  }
  OdeStepper(const OdeStepper&) = delete;
  OdeStepper& operator=(const OdeStepper&) = delete;

  void step(double h) override { dWorldStep(world_, h); }

  BodyState state() const override {
    BodyState s = s0_;
    const dReal* q = dBodyGetQuaternion(body_);
    s.q = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized();
    const dReal* c = dBodyGetPosition(body_);
    s.c = Eigen::Vector3d(c[0], c[1], c[2]);
    const dReal* av = dBodyGetAngularVel(body_);
    const Eigen::Vector3d wb = s.q.conjugate() * Eigen::Vector3d(av[0], av[1], av[2]);
    s.L = s.q * m_.inertia.cwiseProduct(wb);
    return s;
  }

 private:
  const RigidBodyModel& m_;
  BodyState s0_;
  dWorldID world_;
  dBodyID body_;
};

}  // namespace

namespace {
std::vector<PeerConfig> ode_configs() {
  const std::pair<const char*, OdeMode> modes[] = {
      {"ode_default", OdeMode::standard},
      {"ode_gyro_off", OdeMode::gyro_off},
      {"ode_finite_rotation", OdeMode::finite_rotation},
  };
  std::vector<PeerConfig> out;
  for (const auto& [label, mode] : modes) {
    out.push_back(stepped_peer(label, [mode = mode](const RigidBodyModel& m, const BodyState& s0) -> std::unique_ptr<Stepper> {
      return std::make_unique<OdeStepper>(mode, m, s0);
    }));
  }
  return out;
}
}  // namespace

}  // namespace tumble::bench
#endif

namespace tumble::bench {

PeerEngine ode_engine() {
#if TUMBLE_HAVE_ODE
  return {"ODE " TUMBLE_ODE_VERSION " (double precision, libode-dev)",
          "- ODE: one dBody (dMassSetParameters with the principal moments), gravity 0, no joints, dWorldStep(dt), "
          "auto-disable off. `ode_default`: as created (gyroscopic mode on, finite rotation off); `ode_gyro_off`: "
          "dBodySetGyroscopicMode(0); `ode_finite_rotation`: gyroscopic on + dBodySetFiniteRotationMode(1) with no axis "
          "(full finite-rotation update).\n",
          ode_configs()};
#else
  return {"", "- ODE: not found (install libode-dev and re-run CMake)\n", {}};
#endif
}

}  // namespace tumble::bench
