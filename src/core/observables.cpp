#include "core/observables.hpp"

#include <algorithm>
#include <cmath>

#include "core/dynamics.hpp"

namespace tumble {

namespace {

void put(const Eigen::Vector3d& x, double* out) { out[0] = x.x(), out[1] = x.y(), out[2] = x.z(); }

// Row order: the trajectory CSV's columns, then simulate's, with the plot-only
// rows where the plot view lists them (w1..w3 first, |w| and ΔE/E after ω_body).
constexpr Observable kTable[] = {
    {"c", "m", ObservableFrame::world, 3, {"cx", "cy", "cz"}, kTrajectoryColumns | kPythonArray,
     [](const RigidBodyModel&, const BodyState& s, double, double* o) { put(s.c, o); }},
    {"q", "", ObservableFrame::world, 4, {"qw", "qx", "qy", "qz"}, kTrajectoryColumns | kPythonArray,
     [](const RigidBodyModel& m, const BodyState& s, double, double* o) {
       const Eigen::Quaterniond q = cloud_orientation(m, s);  // world ← cloud
       o[0] = q.w(), o[1] = q.x(), o[2] = q.y(), o[3] = q.z();
     },
     PlotHue::none, {}, "world \u2190 cloud (w, x, y, z)"},
    {"v", "m/s", ObservableFrame::world, 3, {"vx", "vy", "vz"}, kTrajectoryColumns | kPythonArray,
     [](const RigidBodyModel& m, const BodyState& s, double, double* o) { put(velocity(m, s), o); }},
    {"omega_world", "rad/s", ObservableFrame::world, 3, {"wx", "wy", "wz"}, kTrajectoryColumns | kPythonArray,
     [](const RigidBodyModel& m, const BodyState& s, double, double* o) { put(omega_world(m, s), o); }},
    {"L", "kg\u00b7m\u00b2/s", ObservableFrame::world, 3, {"Lx", "Ly", "Lz"}, kTrajectoryColumns | kPythonArray,
     [](const RigidBodyModel&, const BodyState& s, double, double* o) { put(s.L, o); }},
    {"energy", "J", ObservableFrame::scalar, 1, {"energy"}, kTrajectoryColumns | kPythonArray,
     [](const RigidBodyModel& m, const BodyState& s, double, double* o) { o[0] = total_energy(m, s); }},
    {"omega_principal", "rad/s", ObservableFrame::principal, 3, {"w1", "w2", "w3"}, kPlotSeries,
     [](const RigidBodyModel& m, const BodyState& s, double, double* o) { put(omega_principal(m, s), o); },
     PlotHue::axes, {"\u03c9\u2081", "\u03c9\u2082", "\u03c9\u2083"}},
    {"omega_body", "rad/s", ObservableFrame::cloud, 3, {"wbx", "wby", "wbz"}, kSimulateColumns | kPythonArray | kPlotSeries,
     [](const RigidBodyModel& m, const BodyState& s, double, double* o) { put(omega_body(m, s), o); },
     PlotHue::greys, {"\u03c9x (cloud axes)", "\u03c9y (cloud axes)", "\u03c9z (cloud axes)"}},
    {"omega_norm", "rad/s", ObservableFrame::scalar, 1, {"|w|"}, kPlotSeries,
     [](const RigidBodyModel& m, const BodyState& s, double, double* o) { o[0] = omega_world(m, s).norm(); },
     PlotHue::omega, {"|\u03c9|"}},
    {"energy_error", "1", ObservableFrame::scalar, 1, {"energy_error"}, kPlotSeries,
     [](const RigidBodyModel& m, const BodyState& s, double e0, double* o) {
       o[0] = (total_energy(m, s) - e0) / std::max(std::abs(e0), 1e-300);
     },
     PlotHue::ink, {"\u0394E/E"}},
    {"axis_L", "rad", ObservableFrame::principal, 3, {"axis1_L", "axis2_L", "axis3_L"}, kSimulateColumns | kPlotSeries,
     [](const RigidBodyModel&, const BodyState& s, double, double* o) { put(principal_axis_angles_to_L(s), o); },
     PlotHue::axes, {"\u2220(e\u2081, L)", "\u2220(e\u2082, L)", "\u2220(e\u2083, L)"}},
};

}  // namespace

std::span<const Observable> observables() { return kTable; }

const Observable* find_column(std::string_view column, std::size_t* component) {
  for (const Observable& o : kTable)
    for (std::size_t i = 0; i < o.size; ++i)
      if (o.columns[i] == column) {
        if (component) *component = i;
        return &o;
      }
  return nullptr;
}

}  // namespace tumble
