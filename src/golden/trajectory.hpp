// Golden physics: trajectory CSVs with the columns of `tumble simulate`
// (t,body,cx,cy,cz,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,Lx,Ly,Lz,energy), compared
// value by value with |actual - expected| <= atol + rtol * |expected|.
#pragma once

#include <string>

#include "io/trajectory_csv.hpp"

namespace tumble::golden {

struct TrajectoryTolerance {
  double rtol = 1e-6;  ///< relative
  double atol = 1e-9;  ///< absolute, in each column's SI unit
};

struct TrajectoryComparison {
  bool pass = false;
  long rows = 0;          ///< rows compared
  double worst = 0;       ///< largest |a - e| / (atol + rtol |e|); <= 1 passes
  std::string summary;    ///< one line: what differs first / worst, or "N rows within ..."
};

/// Compares two CSV texts. Structural problems (header, row count, times,
/// body names, unparsable numbers) fail with a message naming the row.
TrajectoryComparison compare_trajectories(const std::string& actual_csv, const std::string& expected_csv,
                                          const TrajectoryTolerance& tol = {});

}  // namespace tumble::golden
