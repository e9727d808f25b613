// The trajectory CSV of `tumble simulate` and of the golden trajectories: one
// row per body per sample, every number printed so that it reads back to the
// same double. The columns are the observables table's (core/observables.hpp).
#pragma once

#include <string>
#include <string_view>

#include "core/body.hpp"

namespace tumble::io {

/// The header line (without newline): t, body, then the columns of every
/// kTrajectoryColumns observable: "t,body,cx,cy,cz,qw,…,Lz,energy".
const std::string& trajectory_header();

/// Appends the row of body `m` in state `s` at time `t` (s): centre (m), cloud
/// orientation, velocity (m/s), omega_world (rad/s), L (kg m^2/s), total
/// energy (J), all in the world frame; `label` fills the body column.
void append_trajectory_row(std::string& out, double t, std::string_view label, const RigidBodyModel& m,
                           const BodyState& s);

/// `tumble simulate`'s header: the trajectory's, then the kSimulateColumns
/// observables' (appended, so readers by position keep working): omega in the
/// cloud's own axes (rad/s) and the angle of each principal axis to L (rad).
const std::string& simulate_header();

/// The trajectory row of `m` (its name in the body column) plus the kSimulateColumns observables.
void append_simulate_row(std::string& out, double t, const RigidBodyModel& m, const BodyState& s);

}  // namespace tumble::io
