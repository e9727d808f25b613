// Bullet peer: the T-handle as a btRigidBody in a btDiscreteDynamicsWorld.
#if TUMBLE_HAVE_BULLET
#include <btBulletDynamicsCommon.h>

#include <memory>
#include <stdexcept>

#include "bench/peers.hpp"

namespace tumble::bench {

std::vector<std::string> bullet_labels() {
  return {"bullet_none", "bullet_explicit", "bullet_implicit_body", "bullet_implicit_world"};
}

BodyState bullet_run(const std::string& label, const Problem& p, double dt) {
  int flags = 0;
  if (label == "bullet_explicit") flags = BT_ENABLE_GYROSCOPIC_FORCE_EXPLICIT;
  else if (label == "bullet_implicit_body") flags = BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY;
  else if (label == "bullet_implicit_world") flags = BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_WORLD;
  else if (label != "bullet_none") throw std::invalid_argument("unknown Bullet configuration " + label);

  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher(&config);
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
  world.setGravity(btVector3(0, 0, 0));

  btSphereShape shape(0.1);
  const Eigen::Vector3d& I = p.model.inertia;
  btRigidBody::btRigidBodyConstructionInfo info(p.model.mass, nullptr, &shape, btVector3(I.x(), I.y(), I.z()));
  const Eigen::Quaterniond& q0 = p.s0.q;
  info.m_startWorldTransform.setRotation(btQuaternion(q0.x(), q0.y(), q0.z(), q0.w()));
  info.m_startWorldTransform.setOrigin(btVector3(p.s0.c.x(), p.s0.c.y(), p.s0.c.z()));
  btRigidBody body(info);
  body.setFlags(flags);
  body.setActivationState(DISABLE_DEACTIVATION);
  const Eigen::Vector3d w = p.s0.q * p.model.inv_inertia.cwiseProduct(p.s0.q.conjugate() * p.s0.L);
  body.setAngularVelocity(btVector3(w.x(), w.y(), w.z()));
  world.addRigidBody(&body);

  const long n = std::max(1L, std::lround(p.duration / dt));
  const double h = p.duration / static_cast<double>(n);
  for (long i = 0; i < n; ++i) world.stepSimulation(h, 0);

  BodyState s;
  const btTransform& tr = body.getWorldTransform();
  const btQuaternion r = tr.getRotation();
  s.q = Eigen::Quaterniond(r.w(), r.x(), r.y(), r.z()).normalized();
  s.c = Eigen::Vector3d(tr.getOrigin().x(), tr.getOrigin().y(), tr.getOrigin().z());
  const btVector3 av = body.getAngularVelocity();
  const Eigen::Vector3d wb = s.q.conjugate() * Eigen::Vector3d(av.x(), av.y(), av.z());
  s.L = s.q * p.model.inertia.cwiseProduct(wb);
  s.P = p.s0.P;
  world.removeRigidBody(&body);
  return s;
}

}  // namespace tumble::bench
#endif
