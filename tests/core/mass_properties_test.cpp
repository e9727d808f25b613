// Mass properties of particle clouds (seed §6, erratum 2): M, c, J0 about c,
// ascending principal moments, a right-handed principal frame, the principal
// box, and the documented errors for degenerate clouds.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "core/error.hpp"
#include "core/mass_properties.hpp"
#include "reference_problem.hpp"

namespace tumble {
namespace {

TEST(MassProperties, ReferenceCloudHasMoments123) {
  const MassProperties mp = compute_mass_properties(testing::reference_cloud(), "ref");
  EXPECT_DOUBLE_EQ(mp.mass, 3.0);
  EXPECT_NEAR(mp.principal_moments[0], 1.0, 1e-15);
  EXPECT_NEAR(mp.principal_moments[1], 2.0, 1e-15);
  EXPECT_NEAR(mp.principal_moments[2], 3.0, 1e-15);
  EXPECT_NEAR(mp.principal_axes.determinant(), 1.0, 1e-15);
}

// A lattice box of n³ cell-centred particles has Σx² = N a²(1 - 1/n²)/12 per axis,
// so J_xx = M(b² + c²)/12 · (1 - 1/n²): the relative error is exactly 1/n² and
// falls by 4 per doubling of n.
TEST(MassProperties, LatticeBoxConvergesToSolidBox) {
  const Eigen::Vector3d size(1.0, 2.0, 3.0);
  const double M = 2.0;
  const Eigen::Vector3d solid(M * (size.y() * size.y() + size.z() * size.z()) / 12,
                              M * (size.x() * size.x() + size.z() * size.z()) / 12,
                              M * (size.x() * size.x() + size.y() * size.y()) / 12);
  double prev = INFINITY;
  for (int n : {2, 4, 8, 16, 32}) {
    const MassProperties mp = compute_mass_properties(make_box(size, Eigen::Vector3i::Constant(n), M), "box");
    EXPECT_NEAR(mp.mass, M, 1e-13);
    EXPECT_LT(mp.com.norm(), 1e-14);
    const Eigen::Vector3d diag = mp.inertia.diagonal();
    const double err = ((diag - solid).cwiseQuotient(solid)).cwiseAbs().maxCoeff();
    EXPECT_NEAR(err, 1.0 / (n * n), 1e-12) << "n=" << n;
    EXPECT_LT(err, prev);
    prev = err;
    EXPECT_LT((mp.inertia - Eigen::Matrix3d(diag.asDiagonal())).norm(), 1e-13);  // no products of inertia
    // Ascending moments: J_zz < J_yy < J_xx, so the principal axes are ±z, ±y, ±x.
    EXPECT_NEAR(mp.principal_moments[0], diag.z(), 1e-13);
    EXPECT_NEAR(mp.principal_moments[1], diag.y(), 1e-13);
    EXPECT_NEAR(mp.principal_moments[2], diag.x(), 1e-13);
    EXPECT_NEAR(std::abs(mp.principal_axes(2, 0)), 1.0, 1e-14);
    EXPECT_NEAR(std::abs(mp.principal_axes(1, 1)), 1.0, 1e-14);
    EXPECT_NEAR(std::abs(mp.principal_axes(0, 2)), 1.0, 1e-14);
    // Box: cell centres span size·(1 - 1/n), centred on c, along the principal axes (z, y, x).
    const Eigen::Vector3d half = 0.5 * size * (1.0 - 1.0 / n);
    EXPECT_LT((mp.box.half_extents - Eigen::Vector3d(half.z(), half.y(), half.x())).norm(), 1e-14) << "n=" << n;
    EXPECT_LT(mp.box.center.norm(), 1e-14);
  }
}

ParticleCloud random_cloud(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> pos(-2.0, 2.0), mass(0.1, 3.0);
  ParticleCloud c;
  for (int i = 0; i < n; ++i) c.push_back({{pos(rng), pos(rng), pos(rng)}, mass(rng)});
  return c;
}

TEST(MassProperties, ParallelAxisShift) {
  std::mt19937 rng(7);
  const ParticleCloud cloud = random_cloud(rng, 40);
  const MassProperties mp = compute_mass_properties(cloud, "random");
  for (const Eigen::Vector3d& d : {Eigen::Vector3d(1.0, -2.0, 0.5), Eigen::Vector3d(-3.0, 0.1, 4.0)}) {
    const Eigen::Matrix3d expected =
        mp.inertia + mp.mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
    EXPECT_LT((inertia_about(cloud, mp.com + d) - expected).norm(), 1e-12 * expected.norm());
  }
}

TEST(MassProperties, RotatedCloudHasRotatedInertia) {
  std::mt19937 rng(11);
  const ParticleCloud cloud = random_cloud(rng, 30);
  const MassProperties mp = compute_mass_properties(cloud, "random");
  const Eigen::Matrix3d R = Eigen::Quaterniond(0.4, -0.7, 0.2, 0.5).normalized().toRotationMatrix();
  const Eigen::Vector3d shift(5.0, -1.0, 2.0);
  ParticleCloud moved;
  for (const Particle& p : cloud) moved.push_back({R * p.position + shift, p.mass});
  const MassProperties mr = compute_mass_properties(moved, "moved");
  EXPECT_LT((mr.com - (R * mp.com + shift)).norm(), 1e-13);
  EXPECT_LT((mr.inertia - R * mp.inertia * R.transpose()).norm(), 1e-12 * mp.inertia.norm());
  EXPECT_LT((mr.principal_moments - mp.principal_moments).norm(), 1e-12 * mp.inertia.norm());
}

TEST(MassProperties, PrincipalFrameIsRightHandedAndDiagonalises) {
  std::mt19937 rng(3);
  for (int trial = 0; trial < 50; ++trial) {
    const MassProperties mp = compute_mass_properties(random_cloud(rng, 4 + trial % 20), "random");
    const Eigen::Matrix3d& A = mp.principal_axes;
    EXPECT_NEAR(A.determinant(), 1.0, 1e-12) << trial;
    EXPECT_LT((A.transpose() * A - Eigen::Matrix3d::Identity()).norm(), 1e-12) << trial;
    EXPECT_LE(mp.principal_moments[0], mp.principal_moments[1]) << trial;
    EXPECT_LE(mp.principal_moments[1], mp.principal_moments[2]) << trial;
    const Eigen::Matrix3d D = A.transpose() * mp.inertia * A;
    EXPECT_LT((D - Eigen::Matrix3d(mp.principal_moments.asDiagonal())).norm(), 1e-12 * mp.inertia.norm())
        << trial;
    EXPECT_TRUE(mp.principal_rotation().toRotationMatrix().isApprox(A, 1e-12)) << trial;
  }
}

// Each degenerate cloud throws DegenerateBody (an InputError) whose message names
// the body and says what is wrong and what to do.
void expect_degenerate(const ParticleCloud& cloud, const std::vector<std::string>& fragments) {
  try {
    compute_mass_properties(cloud, "wing nut");
    ADD_FAILURE() << "expected DegenerateBody";
  } catch (const DegenerateBody& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'wing nut'"), std::string::npos) << what;
    for (const std::string& f : fragments) EXPECT_NE(what.find(f), std::string::npos) << what << " lacks " << f;
    const InputError& as_input = e;  // maps to the app's input-error exit code
    (void)as_input;
  }
}

TEST(MassProperties, DegenerateCloudsThrowDocumentedErrors) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const Eigen::Vector3d x(1, 0, 0), y(0, 1, 0);
  expect_degenerate({}, {"empty", "particles"});
  expect_degenerate({{x, 1.0}, {y, 0.0}, {-x, 1.0}}, {"particle 1", "mass 0", "> 0"});
  expect_degenerate({{x, 1.0}, {y, 1.0}, {-x, -2.0}}, {"particle 2", "mass -2", "> 0"});
  expect_degenerate({{x, nan}, {y, 1.0}, {-x, 1.0}}, {"particle 0", "finite"});
  expect_degenerate({{x, inf}, {y, 1.0}, {-x, 1.0}}, {"particle 0", "finite"});
  expect_degenerate({{x, 1.0}, {Eigen::Vector3d(0, nan, 0), 1.0}, {-x, 1.0}}, {"particle 1", "non-finite coordinate"});
  expect_degenerate({{Eigen::Vector3d(0.3, -1, 2), 2.0}}, {"single point mass", "three non-collinear"});
  // Collinear along a generic direction (not a cloud axis), and two particles.
  const Eigen::Vector3d dir = Eigen::Vector3d(1, 2, -0.5).normalized();
  ParticleCloud rod;
  for (int i = 0; i < 7; ++i) rod.push_back({Eigen::Vector3d(0.1, 0.2, 0.3) + (i - 3) * 0.37 * dir, 1.0 + i});
  expect_degenerate(rod, {"collinear", "thickness"});
  expect_degenerate({{x, 1.0}, {-x, 1.0}}, {"collinear", "thickness"});
}

}  // namespace
}  // namespace tumble
