#include <gtest/gtest.h>

#include <cstdlib>
#include <sstream>
#include <vector>

#include "core/dynamics.hpp"
#include "io/trajectory_csv.hpp"

namespace tumble::io {
namespace {

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  for (std::string f; std::getline(in, f, ',');) out.push_back(f);
  return out;
}

TEST(TrajectoryCsv, RowHasTheHeaderColumnsAndReadsBackExactly) {
  RigidBodyModel m;
  m.name = "box";
  m.mass = 2;
  m.inertia = {1, 2, 3};
  m.inv_inertia = {1, 0.5, 1.0 / 3.0};
  BodyState s;
  s.c = {0.1, -2, 1e-17};
  s.P = {2, 4, 6};  // v = (1, 2, 3)
  s.L = {0.3, 0.2, 0.1};
  std::string out;
  append_trajectory_row(out, 1.0 / 3.0, "rk4:box", m, s);
  ASSERT_EQ(out.back(), '\n');
  out.pop_back();
  const auto f = fields(out), names = fields(trajectory_header());
  ASSERT_EQ(f.size(), names.size());
  EXPECT_EQ(std::strtod(f[0].c_str(), nullptr), 1.0 / 3.0);
  EXPECT_EQ(f[1], "rk4:box");
  EXPECT_EQ(std::strtod(f[4].c_str(), nullptr), 1e-17);
  EXPECT_EQ(f[9], "1");
  EXPECT_EQ(f[11], "3");
  EXPECT_EQ(std::strtod(f[18].c_str(), nullptr), total_energy(m, s));
}

// The headers are the CSV's contract with its readers (goldens, scripts): the
// observables table must write them byte for byte.
TEST(TrajectoryCsv, HeadersAreTheDocumentedColumns) {
  EXPECT_EQ(trajectory_header(), "t,body,cx,cy,cz,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,Lx,Ly,Lz,energy");
  EXPECT_EQ(simulate_header(), trajectory_header() + ",wbx,wby,wbz,axis1_L,axis2_L,axis3_L");
}

TEST(TrajectoryCsv, SimulateRowIsTheTrajectoryRowThenOmegaBodyAndTheAnglesToL) {
  RigidBodyModel m;
  m.name = "box";
  m.mass = 2;
  m.inertia = {1, 2, 3};
  m.inv_inertia = {1, 0.5, 1.0 / 3.0};
  BodyState s;
  s.L = {0.3, 0.2, 0.1};
  std::string traj, sim;
  append_trajectory_row(traj, 0.5, "box", m, s);
  append_simulate_row(sim, 0.5, m, s);
  traj.pop_back();
  ASSERT_EQ(sim.rfind(traj, 0), 0u);  // the trajectory's columns first
  sim.pop_back();
  const auto f = fields(sim);
  ASSERT_EQ(f.size(), fields(simulate_header()).size());
  const Eigen::Vector3d wb = omega_body(m, s), a = principal_axis_angles_to_L(s);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(std::strtod(f[19 + i].c_str(), nullptr), wb[i]);
    EXPECT_EQ(std::strtod(f[22 + i].c_str(), nullptr), a[i]);
  }
}

}  // namespace
}  // namespace tumble::io
