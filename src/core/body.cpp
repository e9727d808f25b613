#include "core/body.hpp"

namespace tumble {

RigidBodyModel make_model(const std::string& name, const MassProperties& mp, const ForceSet& forces) {
  RigidBodyModel m;
  m.name = name;
  m.mass = mp.mass;
  m.inertia = mp.principal_moments;
  m.inv_inertia = mp.principal_moments.cwiseInverse();
  m.cloud_from_principal = mp.principal_rotation().normalized();
  m.com_cloud = mp.com;
  m.box = mp.box;
  m.forces = forces;
  return m;
}

BodyState make_state(const RigidBodyModel& m, const InitialConditions& ic) {
  BodyState s;
  s.c = ic.position;
  s.q = (ic.orientation.normalized() * m.cloud_from_principal).normalized();
  s.P = m.mass * ic.velocity;
  const Eigen::Vector3d omega_p = ic.omega_frame == Frame::body
                                      ? m.cloud_from_principal.conjugate() * ic.omega
                                      : s.q.conjugate() * ic.omega;
  s.L = s.q * m.inertia.cwiseProduct(omega_p);
  return s;
}

}  // namespace tumble
