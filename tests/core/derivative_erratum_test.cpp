// Seed erratum 1: the seed's q' = ½ Q(q) ω with its 4×3 Q(q) forms q ⊗ ω, which
// is right only for a body-frame ω. Fed the world ω = J⁻¹(t) L the seed
// prescribes (the "mixed" form), it loses the energy and the intermediate-axis
// flip on the reference problem; the project's derivative (½ ω_world ⊗ q) keeps
// both.
#include <gtest/gtest.h>

#include <cmath>

#include "core/dynamics.hpp"
#include "core/methods/explicit_rk.hpp"
#include "core/methods/free_rotation_exact.hpp"
#include "reference_problem.hpp"

namespace tumble {
namespace {

// The seed's Q(q), rows (qx', qy', qz', qw') — Eigen's coefficient order.
Eigen::Matrix<double, 4, 3> seed_Q(const Eigen::Quaterniond& q) {
  const double x = q.x(), y = q.y(), z = q.z(), w = q.w();
  Eigen::Matrix<double, 4, 3> Q;
  Q << +w, -z, +y,
       +z, +w, -x,
       -y, +x, +w,
       -x, -y, -z;
  return Q;
}

// The erratum's corrected matrix (world ω): rows [+w +z -y], [-z +w +x], [+y -x +w], [-x -y -z].
Eigen::Matrix<double, 4, 3> corrected_Q(const Eigen::Quaterniond& q) {
  const double x = q.x(), y = q.y(), z = q.z(), w = q.w();
  Eigen::Matrix<double, 4, 3> Q;
  Q << +w, +z, -y,
       -z, +w, +x,
       +y, -x, +w,
       -x, -y, -z;
  return Q;
}

// The mixed form: the seed's Q(q) applied to the world-frame ω.
Derivative seed_mixed_derivative(const RigidBodyModel& m, const BodyState& s, double t) {
  Derivative d = derivative(m, s, t);
  d.dq = 0.5 * seed_Q(s.q) * omega_world(m, s);
  return d;
}

TEST(DerivativeErratum, SeedMatrixIsRightProductCorrectedIsLeftProduct) {
  const Eigen::Quaterniond q = Eigen::Quaterniond(0.3, -0.5, 0.7, 0.2).normalized();
  const Eigen::Vector3d w(0.4, -1.1, 2.3);
  EXPECT_LT((seed_Q(q) * w - (q * pure(w)).coeffs()).norm(), 1e-15);
  EXPECT_LT((corrected_Q(q) * w - (pure(w) * q).coeffs()).norm(), 1e-15);
  // The two differ for a general orientation.
  EXPECT_GT((seed_Q(q) * w - corrected_Q(q) * w).norm(), 0.1);
  // And the project's derivative is the corrected (world) form, equivalently ½ q ⊗ ω_body.
  const RigidBodyModel m = testing::reference_model();
  BodyState s;
  s.q = q;
  s.L = q * Eigen::Vector3d(0.5, -1.0, 2.0);
  const Derivative d = derivative(m, s, 0.0);
  EXPECT_LT((d.dq - 0.5 * corrected_Q(q) * omega_world(m, s)).norm(), 1e-15);
  EXPECT_LT((d.dq - 0.5 * seed_Q(q) * omega_principal(m, s)).norm(), 1e-15);
}

struct RunSummary {
  double max_rel_energy_error = 0;
  double final_rel_energy_error = 0;
  int sign_changes = 0;
  Eigen::Vector3d omega_end;
};

RunSummary integrate(const DerivativeFn& f) {
  const RigidBodyModel m = testing::reference_model();
  BodyState s = testing::reference_state(m);
  const double e0 = kinetic_energy(m, s);
  const double h = 1e-3;
  RunSummary r;
  double wy_prev = omega_body(m, s).y();
  for (int i = 0; i < 10000; ++i) {
    s = explicit_rk_step(kRk4Tableau, f, m, s, i * h, h);
    r.max_rel_energy_error = std::max(r.max_rel_energy_error, std::abs(kinetic_energy(m, s) - e0) / e0);
    const double wy = omega_body(m, s).y();
    if ((wy < 0) != (wy_prev < 0)) ++r.sign_changes;
    wy_prev = wy;
  }
  r.omega_end = omega_body(m, s);
  r.final_rel_energy_error = std::abs(kinetic_energy(m, s) - e0) / e0;
  return r;
}

TEST(DerivativeErratum, MixedFormLosesEnergyAndFlipProjectFormKeepsBoth) {
  const RigidBodyModel m = testing::reference_model();
  const BodyState s0 = testing::reference_state(m);
  EXPECT_NEAR(kinetic_energy(m, s0), 100.0002, 1e-12);  // ½(1·0.01² + 2·10² + 3·0.01²)
  const Eigen::Vector3d w_exact = FreeRotationExact(m.inertia, s0.q, s0.L).omega_body(10.0);
  // The seed's numbers for the mid-flip state at t = 10 s.
  EXPECT_LT((w_exact - Eigen::Vector3d(4.47, 8.95, 2.58)).norm(), 0.01) << w_exact.transpose();

  const RunSummary mixed = integrate(seed_mixed_derivative);
  std::printf("mixed form: max |dE|/E = %.3e, sign changes of w_y = %d, w(10) = %s\n",
              mixed.max_rel_energy_error, mixed.sign_changes,
              ::testing::PrintToString(mixed.omega_end.transpose()).c_str());
  EXPECT_GT(mixed.max_rel_energy_error, 1e-7);
  EXPECT_GT(mixed.final_rel_energy_error, 1e-7);  // seed: 100.00020 -> 100.00024
  EXPECT_EQ(mixed.sign_changes, 0);                              // never flips
  EXPECT_GT(mixed.omega_end.y(), 9.9);                           // stays near (0, 10, 0)
  EXPECT_LT(std::hypot(mixed.omega_end.x(), mixed.omega_end.z()), 0.5);

  const RunSummary project = integrate(derivative);
  std::printf("project form: final |dE|/E = %.3e, max |dE|/E = %.3e, sign changes of w_y = %d, w(10) = %s\n",
              project.final_rel_energy_error, project.max_rel_energy_error, project.sign_changes,
              ::testing::PrintToString(project.omega_end.transpose()).c_str());
  EXPECT_LT(project.final_rel_energy_error, 1e-9);  // "keeps the energy to 9 digits"
  EXPECT_LT(project.max_rel_energy_error, 2e-9);    // ~1e-9 all along, no drift
  EXPECT_EQ(project.sign_changes, 4);               // the Dzhanibekov flips
  // Mid-flip at t = 10 s, where ω turns fast: RK4's ~2e-3 rad phase error at
  // dt = 1e-3 allows a few 1e-2 rad/s; the unflipped mixed form is ~5 rad/s away.
  EXPECT_LT((project.omega_end - w_exact).norm(), 0.05);
  EXPECT_GT((mixed.omega_end - w_exact).norm(), 1.0);
}

}  // namespace
}  // namespace tumble
