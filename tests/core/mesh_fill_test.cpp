// Particle clouds from meshes: the inside test, convergence to the exact tensor, surface samples.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <tuple>

#include "core/mass_properties.hpp"
#include "core/mesh_fill.hpp"
#include "mesh_shapes.hpp"

namespace tumble {
namespace {

using test::box_mesh;
using test::icosphere;
using test::lumpy_mesh;

double rel(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) { return (a - b).norm() / b.norm(); }

std::set<std::tuple<double, double, double>> point_set(const ParticleCloud& c) {
  std::set<std::tuple<double, double, double>> s;
  for (const Particle& p : c) s.insert({p.position.x(), p.position.y(), p.position.z()});
  return s;
}

TEST(VolumeFill, AlignedBoxGivesTheBoxLattice) {
  const TriangleMesh m = box_mesh({1.0, 0.6, 0.4});
  const VolumeFill f = fill_volume(m, true, {0.1, Eigen::Vector3d::Constant(0.5)}, 2.4);
  ASSERT_EQ(f.cloud.size(), 240u);
  EXPECT_EQ(f.winding_evaluations, 0u);
  const MassProperties a = compute_mass_properties(f.cloud, "mesh");
  const MassProperties b = compute_mass_properties(make_box({1.0, 0.6, 0.4}, {10, 6, 4}, 2.4), "box");
  EXPECT_NEAR(a.mass, 2.4, 1e-12);
  EXPECT_LT(rel(a.inertia, b.inertia), 1e-12);
}

// A turned lattice keeps exactly its points that lie in the box (brute force
// over every node of the turned lattice), by ray crossings and by winding number.
TEST(VolumeFill, TurnedLatticeKeepsItsPointsInsideTheBox) {
  const TriangleMesh m = box_mesh({1.0, 0.6, 0.4});  // centred on the origin
  for (int k = 0; k < 6; ++k) {
    UnitRandom rnd(100 + k);
    const Eigen::Quaterniond q = Eigen::Quaterniond(rnd() - 0.5, rnd() - 0.5, rnd() - 0.5, rnd() - 0.5).normalized();
    const LatticeSpec l{0.07, Eigen::Vector3d(rnd(), rnd(), rnd()), q};
    // Nodes of the turned lattice, anchored anywhere: whole spacings do not matter.
    Eigen::Vector3d lo(1e9, 1e9, 1e9);
    for (const auto& v : m.vertices) lo = lo.cwiseMin(q.conjugate() * v);
    std::size_t inside = 0;
    for (int i = -30; i <= 30; ++i)
      for (int j = -30; j <= 30; ++j)
        for (int n = -30; n <= 30; ++n) {
          const Eigen::Vector3d p = q * (lo + l.spacing * (Eigen::Vector3d(i, j, n) + l.offset));
          inside += std::abs(p.x()) < 0.5 && std::abs(p.y()) < 0.3 && std::abs(p.z()) < 0.2;
        }
    EXPECT_EQ(fill_volume(m, true, l, 1.0).cloud.size(), inside) << k;
    EXPECT_EQ(fill_volume(m, false, l, 1.0).cloud.size(), inside) << k;
  }
}

// The per-row crossing count must agree with the winding number at every
// lattice point of a non-convex mesh, rows through vertices and edges included.
TEST(VolumeFill, RowCrossingsAgreeWithWindingNumber) {
  for (const Eigen::Vector3d& offset : {Eigen::Vector3d(0.37, 0.61, 0.13), Eigen::Vector3d(0.5, 0.5, 0.5)}) {
    const TriangleMesh m = lumpy_mesh(3);
    const LatticeSpec l{0.06, offset};
    const VolumeFill rows = fill_volume(m, true, l, 1.0);
    const VolumeFill gwn = fill_volume(m, false, l, 1.0);
    EXPECT_GT(rows.cloud.size(), 10000u);
    EXPECT_GT(gwn.winding_evaluations, 0u);
    EXPECT_EQ(point_set(rows.cloud), point_set(gwn.cloud));
    // Spot-check the winding number itself at the points found.
    for (std::size_t i = 0; i < rows.cloud.size(); i += 997)
      EXPECT_NEAR(winding_number(m, rows.cloud[i].position), 1.0, 1e-9);
  }
  // Rows along the cube's edges, face diagonals and corners: the top-left rule
  // makes each face a half-open square, so 4 of the 5 rows per axis count.
  const TriangleMesh cube = box_mesh({2, 2, 2});
  EXPECT_EQ(fill_volume(cube, true, {0.5, Eigen::Vector3d(0.5, 0, 0)}, 1.0).cloud.size(), 4u * 4 * 4);
}

// Over its point budget a lattice is counted, not filled; at the budget it is filled.
TEST(VolumeFill, MaxPointsCountsWithoutFilling) {
  const TriangleMesh m = box_mesh({1.0, 0.6, 0.4});
  const LatticeSpec l{0.1, Eigen::Vector3d::Constant(0.5)};
  const VolumeFill over = fill_volume(m, true, l, 1.0, {239});
  EXPECT_EQ(over.lattice_points, 240.0);
  EXPECT_TRUE(over.cloud.empty());
  EXPECT_EQ(fill_volume(m, true, l, 1.0, {240}).cloud.size(), 240u);
  EXPECT_EQ(fill_volume(m, true, l, 1.0).lattice_points, lattice_counts(m, l).prod());
}

TEST(VolumeFill, WindingNumberToleratesASmallHoleNotAnOpenFace) {
  TriangleMesh sphere = icosphere(3, 1.0);
  const LatticeSpec l{0.08, Eigen::Vector3d(0.3, 0.7, 0.2)};
  const std::size_t closed = fill_volume(sphere, true, l, 1.0).cloud.size();
  sphere.triangles.erase(sphere.triangles.begin(), sphere.triangles.begin() + 4);  // 4 of 1280
  const VolumeFill holed = fill_volume(sphere, false, l, 1.0);
  EXPECT_NEAR(double(holed.cloud.size()), double(closed), 0.01 * closed);
  EXPECT_LT(holed.ambiguous, closed / 100);

  TriangleMesh open_box = box_mesh({1, 1, 1});
  open_box.triangles.resize(10);  // the whole +x face gone
  const VolumeFill open = fill_volume(open_box, false, {0.05, Eigen::Vector3d::Constant(0.5)}, 1.0);
  EXPECT_GT(open.ambiguous, 8000u / 10) << "a tenth of the box has w in (0.25, 0.75)";
}

// A randomly offset lattice converges as N^(-2/3) in the RMS over offsets
// (the surface term averages out); fit the slope over a factor 64 in N.
TEST(VolumeFill, RandomlyOffsetLatticeConvergesAsNToMinusTwoThirds) {
  const TriangleMesh m = lumpy_mesh(4);
  const SolidProperties exact = solid_properties(m);
  const Eigen::Matrix3d J = exact.inertia_for_mass(1.0);
  UnitRandom rnd(42);
  std::vector<double> logn, loge;
  for (double h : {0.16, 0.08, 0.04}) {
    double sq = 0, n = 0;
    constexpr int kOffsets = 12;
    for (int k = 0; k < kOffsets; ++k) {
      const VolumeFill f = fill_volume(m, true, {h, Eigen::Vector3d(rnd(), rnd(), rnd())}, 1.0);
      const MassProperties mp = compute_mass_properties(f.cloud, "lumpy");
      sq += std::pow(rel(mp.inertia, J), 2);
      n += double(f.cloud.size());
    }
    logn.push_back(std::log(n / kOffsets));
    loge.push_back(0.5 * std::log(sq / kOffsets));
  }
  const double slope = (loge.back() - loge.front()) / (logn.back() - logn.front());
  EXPECT_NEAR(slope, -2.0 / 3, 0.2) << "errors " << std::exp(loge[0]) << " " << std::exp(loge[1]) << " "
                                    << std::exp(loge[2]);
}

TEST(SurfaceFill, CubeShellMatchesClosedFormAndSamplesApproachIt) {
  const double a = 0.5, M = 3.0;
  const TriangleMesh m = box_mesh(Eigen::Vector3d::Constant(a));
  const SolidProperties shell = shell_properties(m);
  EXPECT_NEAR(shell.volume, 6 * a * a, 1e-12);  // area
  EXPECT_LT(rel(shell.inertia_for_mass(M), 5.0 / 18 * M * a * a * Eigen::Matrix3d::Identity()), 1e-12);
  const ParticleCloud c = fill_surface(m, 100000, M, 7);
  ASSERT_EQ(c.size(), 100000u);
  const MassProperties mp = compute_mass_properties(c, "shell");
  EXPECT_NEAR(mp.mass, M, 1e-9);
  // Monte Carlo: relative error ~ N^(-1/2) = 3e-3.
  EXPECT_LT(rel(mp.inertia, shell.inertia_for_mass(M)), 1e-2);
  for (const Particle& p : c) ASSERT_NEAR(p.position.cwiseAbs().maxCoeff(), a / 2, 1e-12) << "on a face";
}

}  // namespace
}  // namespace tumble
