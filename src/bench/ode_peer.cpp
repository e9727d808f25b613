// ODE peer: the T-handle as one dBody stepped by dWorldStep.
#if TUMBLE_HAVE_ODE
#include <ode/ode.h>

#include <cmath>
#include <stdexcept>

#include "bench/peers.hpp"

namespace tumble::bench {

std::vector<std::string> ode_labels() { return {"ode_default", "ode_gyro_off", "ode_finite_rotation"}; }

BodyState ode_run(const std::string& label, const Problem& p, double dt) {
  if (label != "ode_default" && label != "ode_gyro_off" && label != "ode_finite_rotation")
    throw std::invalid_argument("unknown ODE configuration " + label);
  dInitODE2(0);  // reference counted; paired with dCloseODE below
  dWorldID world = dWorldCreate();
  dWorldSetGravity(world, 0, 0, 0);
  dBodyID b = dBodyCreate(world);
  dMass mass;
  const Eigen::Vector3d& I = p.model.inertia;
  dMassSetParameters(&mass, p.model.mass, 0, 0, 0, I.x(), I.y(), I.z(), 0, 0, 0);
  dBodySetMass(b, &mass);
  const Eigen::Quaterniond& q0 = p.s0.q;
  const dQuaternion qd = {q0.w(), q0.x(), q0.y(), q0.z()};
  dBodySetQuaternion(b, qd);
  const Eigen::Vector3d w = p.s0.q * p.model.inv_inertia.cwiseProduct(p.s0.q.conjugate() * p.s0.L);
  dBodySetAngularVel(b, w.x(), w.y(), w.z());
  dBodySetAutoDisableFlag(b, 0);
  if (label == "ode_gyro_off") dBodySetGyroscopicMode(b, 0);
  if (label == "ode_finite_rotation") dBodySetFiniteRotationMode(b, 1);

  const long n = std::max(1L, std::lround(p.duration / dt));
  const double h = p.duration / static_cast<double>(n);
  for (long i = 0; i < n; ++i) dWorldStep(world, h);

  BodyState s;
  const dReal* q = dBodyGetQuaternion(b);
  s.q = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized();
  const dReal* c = dBodyGetPosition(b);
  s.c = Eigen::Vector3d(c[0], c[1], c[2]);
  const dReal* av = dBodyGetAngularVel(b);
  const Eigen::Vector3d wb = s.q.conjugate() * Eigen::Vector3d(av[0], av[1], av[2]);
  s.L = s.q * p.model.inertia.cwiseProduct(wb);
  s.P = p.s0.P;
  dWorldDestroy(world);
  dCloseODE();
  return s;
}

}  // namespace tumble::bench
#endif
