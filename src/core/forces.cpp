#include "core/forces.hpp"

#include "core/body.hpp"
#include "core/dynamics.hpp"

namespace tumble {

void UniformGravity::add_wrench(const RigidBodyModel& m, const BodyState&, Wrench& w) const { w.force += m.mass * g; }
void UniformGravity::add_kick(const RigidBodyModel& m, const BodyState& s, KickPart& k) const {
  add_wrench(m, s, k.constant);
}
double UniformGravity::potential(const RigidBodyModel& m, const BodyState& s) const { return -m.mass * g.dot(s.c); }

void PointForce::add_wrench(const RigidBodyModel& m, const BodyState& s, Wrench& w) const {
  const Eigen::Quaterniond world_from_cloud = cloud_orientation(m, s);
  const Eigen::Vector3d F = frame == Frame::world ? force : world_from_cloud * force;
  const Eigen::Vector3d r = world_from_cloud * (point - m.com_cloud);
  w.force += F;
  w.torque += r.cross(F);
}
void PointForce::add_kick(const RigidBodyModel& m, const BodyState& s, KickPart& k) const {
  add_wrench(m, s, k.constant);
}

void ConstantTorque::add_wrench(const RigidBodyModel& m, const BodyState& s, Wrench& w) const {
  w.torque += frame == Frame::world ? torque : Eigen::Vector3d(cloud_orientation(m, s) * torque);
}
void ConstantTorque::add_kick(const RigidBodyModel& m, const BodyState& s, KickPart& k) const {
  add_wrench(m, s, k.constant);
}

void LinearDamping::add_wrench(const RigidBodyModel& m, const BodyState& s, Wrench& w) const {
  w.force -= k * velocity(m, s);
}
void AngularDamping::add_wrench(const RigidBodyModel& m, const BodyState& s, Wrench& w) const {
  w.torque -= k * omega_world(m, s);
}

bool ForceSet::has_torque() const {
  for (const ForceTerm& t : terms)
    if (std::visit([](const auto& x) { return x.torques; }, t)) return true;
  return false;
}

bool ForceSet::conserves_energy() const {
  for (const ForceTerm& t : terms)
    if (std::visit([](const auto& x) { return x.work != Work::conservative; }, t)) return false;
  return true;
}

namespace {
// Body keys in the order their terms are summed (after gravity and point forces).
constexpr ForceKind kForceKinds[] = {
    {"torque_world", true, "N·m", [](const Eigen::Vector3d& v, double) -> ForceTerm { return ConstantTorque{v, Frame::world}; }},
    {"torque_body", true, "N·m", [](const Eigen::Vector3d& v, double) -> ForceTerm { return ConstantTorque{v, Frame::body}; }},
    {"linear_damping", false, "N·s/m", [](const Eigen::Vector3d&, double x) -> ForceTerm { return LinearDamping{x}; }},
    {"angular_damping", false, "N·m·s", [](const Eigen::Vector3d&, double x) -> ForceTerm { return AngularDamping{x}; }},
};
}  // namespace

std::span<const ForceKind> force_kinds() { return kForceKinds; }

}  // namespace tumble
