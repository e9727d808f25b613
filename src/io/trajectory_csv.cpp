#include "io/trajectory_csv.hpp"

#include "base/format.hpp"
#include "core/observables.hpp"

namespace tumble::io {

namespace {

std::string header(unsigned use) {
  std::string h = "t,body";
  for (const Observable& o : observables())
    if (o.use & use)
      for (std::size_t i = 0; i < o.size; ++i) (h += ',') += o.columns[i];
  return h;
}

// The columns of the observables with `use` (energy at t = 0 is not a column: 0).
void append_columns(std::string& out, unsigned use, const RigidBodyModel& m, const BodyState& s) {
  double v[kMaxComponents];
  for (const Observable& o : observables()) {
    if (!(o.use & use)) continue;
    o.value(m, s, 0, v);
    for (std::size_t i = 0; i < o.size; ++i) {
      out += ',';
      out += format_number(v[i]);
    }
  }
}

}  // namespace

const std::string& trajectory_header() {
  static const std::string h = header(kTrajectoryColumns);
  return h;
}

const std::string& simulate_header() {
  static const std::string h = header(kTrajectoryColumns | kSimulateColumns);
  return h;
}

void append_trajectory_row(std::string& out, double t, std::string_view label, const RigidBodyModel& m,
                           const BodyState& s) {
  out += format_number(t);
  out += ',';
  out += label;
  append_columns(out, kTrajectoryColumns, m, s);
  out += '\n';
}

void append_simulate_row(std::string& out, double t, const RigidBodyModel& m, const BodyState& s) {
  out += format_number(t);
  out += ',';
  out += m.name;
  append_columns(out, kTrajectoryColumns | kSimulateColumns, m, s);
  out += '\n';
}

}  // namespace tumble::io
