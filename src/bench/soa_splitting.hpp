// Many torque-free bodies stepped by `splitting` (NO_SQUISH / Dullweber–
// Leimkuhler–McLachlan 1997) in structure-of-arrays form: the same arithmetic as
// core's splitting_step, laid out so the compiler streams it and two threads
// share the bodies.
#pragma once

#include <cstddef>
#include <vector>

#include "core/body.hpp"

namespace tumble::bench {

class BodiesSoA {
 public:
  /// Adds a torque-free body (forces are ignored: this kernel is the free path).
  void push(const RigidBodyModel& m, const BodyState& s);
  size_t size() const { return qw_.size(); }
  BodyState state(size_t i) const;

  /// Advances every body by `steps` steps of h (s) on `threads` threads (bodies
  /// are independent, so each thread takes a contiguous block and keeps small
  /// tiles of bodies in cache across all steps).
  void advance(double h, long steps, int threads);

 private:
  void advance_range(size_t begin, size_t end, double h, long steps);

  std::vector<double> qw_, qx_, qy_, qz_, Lx_, Ly_, Lz_, cx_, cy_, cz_, Px_, Py_, Pz_, mass_, ix_, iy_, iz_;
};

}  // namespace tumble::bench
