#include "core/body_frame.hpp"

#include "core/body_frame_tuned.hpp"
#include "core/dynamics.hpp"

namespace tumble {

BodyCoords to_body_coords(const BodyState& s) {
  BodyCoords x;
  x.c = s.c;
  x.q = s.q;
  x.P = s.P;
  x.pi = momentum_body(s);
  return x;
}

BodyState from_body_coords(const BodyCoords& x) {
  BodyState s;
  s.c = x.c;
  s.q = x.q.normalized();
  s.P = x.P;
  s.L = s.q * x.pi;
  return s;
}

BodyState state_of(const BodyCoords& x) {
  BodyState s;
  s.c = x.c;
  s.q = unit_quaternion(x.q.x(), x.q.y(), x.q.z(), x.q.w());
  s.P = x.P;
  s.L = s.q * x.pi;
  return s;
}

double kinetic_energy(const RigidBodyModel& m, const BodyCoords& x) {
  return 0.5 * x.P.squaredNorm() / m.mass + rotational_energy(m, x.pi);
}

bool all_finite(const BodyCoords& x) {
  return x.c.allFinite() && x.q.coeffs().allFinite() && x.P.allFinite() && x.pi.allFinite();
}

BodyRate body_rate(const RigidBodyModel& m, const BodyCoords& x, double t) {
  BodyRate d;
  const Eigen::Vector3d w = m.inv_inertia.cwiseProduct(x.pi);  // ω_body, rad/s
  d.dc = x.P / m.mass;
  // q' = ½ Q(q) ω_body, the seed's matrix form: (w ω/2 + u × ω/2, -u·ω/2).
  const Eigen::Vector3d wh = 0.5 * w;
  d.dq << x.q.w() * wh + x.q.vec().cross(wh), -x.q.vec().dot(wh);
  d.dpi = x.pi.cross(w);
  if (m.forces.empty()) {
    d.dP.setZero();
  } else {
    const BodyState s = from_body_coords(x);
    const Wrench f = wrench(m, s, t);
    d.dP = f.force;
    d.dpi += s.q.conjugate() * f.torque;
  }
  return d;
}

BodyCoords add_scaled(const BodyCoords& x, double h, const BodyRate& d) {
  BodyCoords o;
  o.c = x.c + h * d.dc;
  o.q.coeffs() = x.q.coeffs() + h * d.dq;
  o.P = x.P + h * d.dP;
  o.pi = x.pi + h * d.dpi;
  return o;
}

BodyCoords rk4_coords_reference(const RigidBodyModel& m, const BodyCoords& x, double t, double h) {
  const double ha = h * 0.5, b1 = h * (1.0 / 6), b2 = h * (1.0 / 3);
  const BodyRate k1 = body_rate(m, x, t);
  const BodyRate k2 = body_rate(m, add_scaled(x, ha, k1), t + 0.5 * h);
  const BodyRate k3 = body_rate(m, add_scaled(x, ha, k2), t + 0.5 * h);
  const BodyRate k4 = body_rate(m, add_scaled(x, h, k3), t + h);
  BodyCoords y;
  y.c = x.c + (((b1 * k1.dc + b2 * k2.dc) + b2 * k3.dc) + b1 * k4.dc);
  y.q.coeffs() = x.q.coeffs() + (((b1 * k1.dq + b2 * k2.dq) + b2 * k3.dq) + b1 * k4.dq);
  y.P = x.P + (((b1 * k1.dP + b2 * k2.dP) + b2 * k3.dP) + b1 * k4.dP);
  // Π compensated: d = ΔΠ − lost, Π' = Π + d, lost' = (Π' − Π) − d.
  const Eigen::Vector3d d = (((b1 * k1.dpi + b2 * k2.dpi) + b2 * k3.dpi) + b1 * k4.dpi) - x.lost_pi;
  y.pi = x.pi + d;
  y.lost_pi = (y.pi - x.pi) - d;
  return y;
}

BodyState rk4_body_reference(const RigidBodyModel& m, const BodyState& s, double t, double h) {
  return state_of(rk4_coords_reference(m, to_body_coords(s), t, h));
}

void rk4_coords_step(const RigidBodyModel& m, BodyCoords& x, double t, double h) {
  if (m.forces.empty()) tuned::rk4_coords_free_inplace(m, x, h);
  else x = rk4_coords_reference(m, x, t, h);
}

BodyState rk4_body_step(const RigidBodyModel& m, const BodyState& s, double t, double h) {
  if (m.forces.empty()) return tuned::rk4_body_free(m, s, h);
  return rk4_body_reference(m, s, t, h);
}

}  // namespace tumble
