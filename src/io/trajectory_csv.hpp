// The trajectory CSV of `tumble simulate` and of the golden trajectories: one
// row per body per sample, every number printed so that it reads back to the
// same double.
#pragma once

#include <string>
#include <string_view>

#include "core/body.hpp"

namespace tumble::io {

/// The header line (without newline).
inline constexpr const char* kTrajectoryHeader = "t,body,cx,cy,cz,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,Lx,Ly,Lz,energy";

/// Appends the row of body `m` in state `s` at time `t` (s): centre (m), cloud
/// orientation, velocity (m/s), omega_world (rad/s), L (kg m^2/s), total
/// energy (J), all in the world frame; `label` fills the body column.
void append_trajectory_row(std::string& out, double t, std::string_view label, const RigidBodyModel& m,
                           const BodyState& s);

}  // namespace tumble::io
