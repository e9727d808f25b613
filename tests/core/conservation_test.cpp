// Invariants of torque-free motion under the geometric methods.
//  - the rows the method table marks geometric (implicit_midpoint, splitting,
//    splitting4, exact) leave world L untouched (it is the exact invariant;
//    they only rotate q), so it holds to 1e-12 over 1e5 steps; those that do not
//    split (implicit_midpoint, exact) also keep the energy to round-off.
//  - splitting is symplectic: its energy error stays bounded, with no drift,
//    over 1e6 steps (max |ΔE| over the last tenth of the run is no larger than
//    over the first tenth, up to a factor 2; a linear drift would give ~10).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/dynamics.hpp"
#include "core/integrator.hpp"
#include "core/methods/rotation_steps.hpp"
#include "reference_problem.hpp"
#include "test_helpers.hpp"

namespace tumble {
namespace {

TEST(Conservation, WorldAngularMomentumOver1e5Steps) {
  const RigidBodyModel m = testing::reference_model();
  const BodyState s0 = testing::reference_state(m);
  const double e0 = kinetic_energy(m, s0);
  int geometric = 0;
  for (Method method : kAllMethods) {
    if (!method_info(method).geometric) continue;
    ++geometric;
    BodyState s = s0;
    const double h = 1e-3;
    double worst_L = 0, worst_pi = 0, worst_e = 0;
    for (long i = 0; i < 100000; ++i) {
      s = step(method, m, s, i * h, h);
      if (i % 100 == 99) {
        worst_L = std::max(worst_L, (s.L - s0.L).norm() / s0.L.norm());
        // |Π| = |Rᵀ L| checks that q stayed a rotation.
        worst_pi = std::max(worst_pi, std::abs(momentum_body(s).norm() - s0.L.norm()) / s0.L.norm());
        worst_e = std::max(worst_e, std::abs(kinetic_energy(m, s) - e0) / e0);
      }
    }
    std::printf("%-18s 1e5 steps: max |dL|/|L| = %.2e, max d|Pi|/|L| = %.2e, max |dE|/E = %.2e\n",
                testing::name_of(method).c_str(), worst_L, worst_pi, worst_e);
    EXPECT_LE(worst_L, 1e-12) << testing::name_of(method);
    EXPECT_LE(worst_pi, 1e-12) << testing::name_of(method);
    // The midpoint rule keeps every quadratic invariant (GNI IV.2.1) and `exact`
    // is the flow itself: energy to round-off (1e5 steps × ~1e-16, random walk).
    if (!method_info(method).splits_free_rotation) {
      EXPECT_LE(worst_e, 1e-12) << testing::name_of(method);
    }
  }
  EXPECT_EQ(geometric, 4) << "implicit_midpoint, splitting, splitting4 and exact are geometric";
}

TEST(Conservation, SplittingEnergyBoundedWithoutDriftOver1e6Steps) {
  const RigidBodyModel m = testing::reference_model();
  const BodyState s0 = testing::reference_state(m);
  const double e0 = kinetic_energy(m, s0);
  const long n = 1000000, tenth = n / 10;
  const double h = 1e-3;  // 1000 s, ~360 flips
  BodyState s = s0;
  double first = 0, last = 0, overall = 0;
  for (long i = 0; i < n; ++i) {
    s = splitting_step(m, s, i * h, h);
    const double de = std::abs(kinetic_energy(m, s) - e0) / e0;
    overall = std::max(overall, de);
    if (i < tenth) first = std::max(first, de);
    if (i >= n - tenth) last = std::max(last, de);
  }
  std::printf("splitting 1e6 steps: max |dE|/E first tenth %.3e, last tenth %.3e, overall %.3e\n", first,
              last, overall);
  EXPECT_GT(first, 0.0);
  EXPECT_LE(last, 2 * first);
  EXPECT_LE(overall, 2 * first);
  // Second-order modified energy: |ΔE|/E = O((hΩ)²) with hΩ = 1e-2.
  EXPECT_LT(overall, 1e-3);
}

}  // namespace
}  // namespace tumble
