// Bullet peer: the body as a btRigidBody in a btDiscreteDynamicsWorld.
#include "bench/peers/peer.hpp"

#if TUMBLE_HAVE_BULLET
#include <btBulletDynamicsCommon.h>

#include <memory>

namespace tumble::bench {

namespace {

class BulletStepper final : public Stepper {
 public:
  BulletStepper(int flags, const RigidBodyModel& m, const BodyState& s0)
      : m_(m), s0_(s0), dispatcher_(&config_), world_(&dispatcher_, &broadphase_, &solver_, &config_) {
    world_.setGravity(btVector3(0, 0, 0));
    const Eigen::Vector3d& I = m.inertia;
    btRigidBody::btRigidBodyConstructionInfo info(m.mass, nullptr, &shape_, btVector3(I.x(), I.y(), I.z()));
    const Eigen::Quaterniond& q0 = s0.q;
    info.m_startWorldTransform.setRotation(btQuaternion(q0.x(), q0.y(), q0.z(), q0.w()));
    info.m_startWorldTransform.setOrigin(btVector3(s0.c.x(), s0.c.y(), s0.c.z()));
    body_ = std::make_unique<btRigidBody>(info);
    body_->setFlags(flags);
    body_->setActivationState(DISABLE_DEACTIVATION);
    const Eigen::Vector3d w = s0.q * m.inv_inertia.cwiseProduct(s0.q.conjugate() * s0.L);
    body_->setAngularVelocity(btVector3(w.x(), w.y(), w.z()));
    const Eigen::Vector3d v = s0.P / m.mass;
    body_->setLinearVelocity(btVector3(v.x(), v.y(), v.z()));
    world_.addRigidBody(body_.get());
  }
  ~BulletStepper() override { world_.removeRigidBody(body_.get()); }
  BulletStepper(const BulletStepper&) = delete;
  BulletStepper& operator=(const BulletStepper&) = delete;

  // One internal step of exactly h (maxSubSteps = 0).
  void step(double h) override { world_.stepSimulation(h, 0); }

  BodyState state() const override {
    BodyState s = s0_;
    const btTransform& tr = body_->getWorldTransform();
    const btQuaternion r = tr.getRotation();
    s.q = Eigen::Quaterniond(r.w(), r.x(), r.y(), r.z()).normalized();
    s.c = Eigen::Vector3d(tr.getOrigin().x(), tr.getOrigin().y(), tr.getOrigin().z());
    const btVector3 av = body_->getAngularVelocity();
    const Eigen::Vector3d wb = s.q.conjugate() * Eigen::Vector3d(av.x(), av.y(), av.z());
    s.L = s.q * m_.inertia.cwiseProduct(wb);
    return s;
  }

 private:
  const RigidBodyModel& m_;
  BodyState s0_;
  btDefaultCollisionConfiguration config_;
  btCollisionDispatcher dispatcher_;
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver solver_;
  btDiscreteDynamicsWorld world_;
  btSphereShape shape_{0.1};
  std::unique_ptr<btRigidBody> body_;
};

}  // namespace

namespace {
std::vector<PeerConfig> bullet_configs() {
  const std::pair<const char*, int> flags[] = {
      {"bullet_none", 0},
      {"bullet_explicit", BT_ENABLE_GYROSCOPIC_FORCE_EXPLICIT},
      {"bullet_implicit_body", BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY},
      {"bullet_implicit_world", BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_WORLD},
  };
  std::vector<PeerConfig> out;
  for (const auto& [label, f] : flags) {
    out.push_back(stepped_peer(label, [f = f](const RigidBodyModel& m, const BodyState& s0) -> std::unique_ptr<Stepper> {
      return std::make_unique<BulletStepper>(f, m, s0);
    }));
  }
  return out;
}
}  // namespace

}  // namespace tumble::bench
#endif

namespace tumble::bench {

PeerEngine bullet_engine() {
#if TUMBLE_HAVE_BULLET
  return {"Bullet " TUMBLE_BULLET_VERSION " (double precision, libbullet-dev)",
          "- Bullet: one btRigidBody (mass, local inertia = principal moments, btSphereShape 0.1 m, no damping, "
          "deactivation disabled) in a btDiscreteDynamicsWorld (dbvt broadphase, sequential-impulse solver), gravity 0, "
          "stepSimulation(dt, 0) (one internal step of exactly dt). Rigid-body flags: `bullet_none` 0 (no gyroscopic "
          "term: ω constant), `bullet_explicit` BT_ENABLE_GYROSCOPIC_FORCE_EXPLICIT (the world's default "
          "max gyroscopic force clamp), `bullet_implicit_body` BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY "
          "(Bullet's default), `bullet_implicit_world` BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_WORLD.\n",
          bullet_configs()};
#else
  return {"", "- Bullet: not found (install libbullet-dev and re-run CMake)\n", {}};
#endif
}

}  // namespace tumble::bench
