// The intermediate-axis (Dzhanibekov) flip on the reference problem.
//
// Definition of a flip used here: a sign change of ω·e2 (the body angular
// velocity along the intermediate principal axis), sampled after every step.
// On the reference problem ω·e2 starts at +10 rad/s and sweeps through zero in
// a fraction of a second each time the body turns over, so every flip is one
// sign change and no step of ≤ 1 s can hold two (consecutive flips are ~2.5 s
// apart in the exact solution). The time of a flip is the linear interpolation
// of the zero inside the step that brackets it.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/dynamics.hpp"
#include "core/methods/free_rotation_exact.hpp"
#include "core/integrator.hpp"
#include "reference_problem.hpp"
#include "test_helpers.hpp"

namespace tumble {
namespace {

struct Flip {
  double t;             // interpolated zero of ω·e2, s
  double t_lo, t_hi;    // the step that brackets it
};

std::vector<Flip> flips(Method method, double h, double t_end) {
  const RigidBodyModel m = testing::reference_model();
  BodyState s = testing::reference_state(m);
  std::vector<Flip> out;
  const long n = std::lround(t_end / h);
  double w_prev = omega_principal(m, s).y();
  for (long i = 0; i < n; ++i) {
    s = step(method, m, s, i * h, h);
    const double w = omega_principal(m, s).y();
    if ((w < 0) != (w_prev < 0)) {
      const double t0 = i * h;
      out.push_back({t0 + h * w_prev / (w_prev - w), t0, t0 + h});
    }
    w_prev = w;
  }
  return out;
}

// Zeros of ω·e2 of the exact solution in [0, t_end], by scanning and bisection.
std::vector<double> exact_flip_times(double t_end) {
  const RigidBodyModel m = testing::reference_model();
  const BodyState s0 = testing::reference_state(m);
  const FreeRotationExact ex(m.inertia, s0.q, s0.L);
  auto wy = [&](double t) { return ex.omega_body(t).y(); };
  std::vector<double> out;
  const double scan = 1e-3;
  for (double a = 0; a < t_end; a += scan) {
    double lo = a, hi = std::min(a + scan, t_end);
    if ((wy(lo) < 0) == (wy(hi) < 0)) continue;
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      ((wy(mid) < 0) == (wy(lo) < 0) ? lo : hi) = mid;
    }
    out.push_back(0.5 * (lo + hi));
  }
  return out;
}

TEST(Dzhanibekov, ReferenceCloudAxesArePrincipal) {
  const RigidBodyModel m = testing::reference_model();
  EXPECT_TRUE(m.cloud_from_principal.isApprox(Eigen::Quaterniond::Identity(), 1e-15));
  EXPECT_EQ(m.inertia, Eigen::Vector3d(1, 2, 3));
}

TEST(Dzhanibekov, ExactSolutionFlipsFourTimesFirstAt149) {
  const std::vector<double> t = exact_flip_times(10.0);
  ASSERT_EQ(t.size(), 4u);
  EXPECT_NEAR(t[0], 1.49, 0.005);
  std::printf("exact flips at %s s\n", ::testing::PrintToString(t).c_str());
}

TEST(Dzhanibekov, Rk4AndSplittingFlipFourTimesAtTheExactTimes) {
  const std::vector<double> t_exact = exact_flip_times(10.0);
  ASSERT_EQ(t_exact.size(), 4u);
  for (Method method : {Method::rk4, Method::splitting}) {
    for (double h : {1e-3, 5e-4}) {
      const std::vector<Flip> f = flips(method, h, 10.0);
      ASSERT_EQ(f.size(), 4u) << testing::name_of(method) << " dt=" << h;
      EXPECT_NEAR(f[0].t, 1.49, 0.01) << testing::name_of(method) << " dt=" << h;
      for (size_t k = 0; k < f.size(); ++k)
        EXPECT_NEAR(f[k].t, t_exact[k], 1e-2) << testing::name_of(method) << " dt=" << h << " flip " << k;
    }
  }
}

// `exact` at any dt ≤ 1 s: four flips, each bracketed by the step holding the exact flip.
TEST(Dzhanibekov, ExactMethodFlipsFourTimesAtAnyStep) {
  const std::vector<double> t_exact = exact_flip_times(10.0);
  ASSERT_EQ(t_exact.size(), 4u);
  for (double h : {1.0, 0.5, 0.25, 0.1, 1e-2, 1e-3}) {
    const std::vector<Flip> f = flips(Method::exact, h, 10.0);
    ASSERT_EQ(f.size(), 4u) << "dt=" << h;
    for (size_t k = 0; k < f.size(); ++k) {
      EXPECT_LE(f[k].t_lo, t_exact[k]) << "dt=" << h << " flip " << k;
      EXPECT_GE(f[k].t_hi, t_exact[k]) << "dt=" << h << " flip " << k;
    }
    if (h <= 1e-2) {
      EXPECT_NEAR(f[0].t, 1.49, 0.01) << "dt=" << h;
    }
  }
}

}  // namespace
}  // namespace tumble
