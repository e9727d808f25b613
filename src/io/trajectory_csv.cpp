#include "io/trajectory_csv.hpp"

#include "core/dynamics.hpp"
#include "core/format.hpp"

namespace tumble::io {

void append_trajectory_row(std::string& out, double t, std::string_view label, const RigidBodyModel& m,
                           const BodyState& s) {
  const Eigen::Quaterniond q = cloud_orientation(m, s);
  const Eigen::Vector3d v = velocity(m, s), w = omega_world(m, s);
  const double cols[] = {s.c.x(), s.c.y(), s.c.z(), q.w(), q.x(), q.y(), q.z(), v.x(), v.y(), v.z(),
                         w.x(),   w.y(),   w.z(),   s.L.x(), s.L.y(), s.L.z(), total_energy(m, s)};
  out += format_number(t);
  out += ',';
  out += label;
  for (double c : cols) {
    out += ',';
    out += format_number(c);
  }
  out += '\n';
}

}  // namespace tumble::io
