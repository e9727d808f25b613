// The tree-accelerated winding number against the direct sum it approximates.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/mesh_fill.hpp"
#include "core/winding_tree.hpp"
#include "mesh_shapes.hpp"

namespace tumble {
namespace {

using test::box_mesh;
using test::icosphere;
using test::lumpy_mesh;

// Largest |tree − direct| over random points in a cube of half-side `half` (m)
// around the origin (the meshes have radius ~1: points near, on both sides, and far).
double max_error(const TriangleMesh& m, const WindingTree& tree, double half, int samples, std::uint64_t seed) {
  UnitRandom rnd(seed);
  double worst = 0;
  for (int s = 0; s < samples; ++s) {
    const Eigen::Vector3d p(half * (2 * rnd() - 1), half * (2 * rnd() - 1), half * (2 * rnd() - 1));
    worst = std::max(worst, std::abs(tree.winding_number(p) - winding_number(m, p)));
  }
  return worst;
}

TriangleMesh holed(TriangleMesh m, std::size_t removed) {
  m.triangles.erase(m.triangles.begin(), m.triangles.begin() + std::ptrdiff_t(removed));
  return m;
}

// β = 2 with the order-2 term: measured max errors 0.036 .. 0.073 near the
// meshes (points in [-1.5, 1.5]³) and 0.015 .. 0.038 far (in [-6, 6]³), on
// these meshes of ~5000 triangles; the bounds leave a factor ~2. (Order 2's
// own error falls as distance^-4 for one node, checked by hand; the sum over
// many nodes at 2 radii is what reaches 1e-2.)
TEST(WindingTree, AgreesWithDirectSumNearAndFar) {
  for (const TriangleMesh& m : {lumpy_mesh(4), holed(lumpy_mesh(4), 20), holed(icosphere(4, 1.0), 3)}) {
    const WindingTree tree(m);
    const double near = max_error(m, tree, 1.5, 2000, 7), far = max_error(m, tree, 6.0, 2000, 8);
    EXPECT_LT(near, 0.15);
    EXPECT_LT(far, 0.08);
  }
}

// A tree that never takes the far field (β = ∞), and a mesh in one leaf,
// sum exactly the direct sum's triangles (only the order of summation differs).
TEST(WindingTree, ExactWhenEveryNodeIsNear) {
  const TriangleMesh lumpy = holed(lumpy_mesh(3), 5);
  EXPECT_LT(max_error(lumpy, WindingTree(lumpy, INFINITY), 2.0, 500, 3), 1e-12);
  const TriangleMesh tet = test::tetra_mesh({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1});
  EXPECT_LT(max_error(tet, WindingTree(tet), 3.0, 500, 4), 1e-12);
  EXPECT_EQ(WindingTree(tet).node_count(), 1u);
  EXPECT_EQ(WindingTree(TriangleMesh{}).winding_number(Eigen::Vector3d::Zero()), 0.0);
}

// The inside test w ≥ 0.5 of the tree equals the direct one at every point of
// a lattice around a sphere with a hole, and so does the whole fill.
TEST(WindingTree, InsideDecisionMatchesDirectSumOnALattice) {
  const TriangleMesh m = holed(icosphere(3, 1.0), 2);
  const WindingTree tree(m);
  std::size_t inside = 0, differ = 0;
  double worst = 0;
  for (int i = -14; i <= 14; ++i)
    for (int j = -14; j <= 14; ++j)
      for (int k = -14; k <= 14; ++k) {
        const Eigen::Vector3d p = 0.0765 * Eigen::Vector3d(i + 0.31, j + 0.17, k + 0.43);
        const double direct = winding_number(m, p), fast = tree.winding_number(p);
        worst = std::max(worst, std::abs(direct - fast));
        inside += direct >= 0.5;
        differ += (direct >= 0.5) != (fast >= 0.5);
      }
  EXPECT_GT(inside, 8000u);  // (4/3)π / 0.0765³ ≈ 9300
  EXPECT_EQ(differ, 0u) << "max |tree - direct| " << worst;

  // The fill with the tree against a brute-force direct fill of the same lattice.
  const LatticeSpec l{0.1, Eigen::Vector3d(0.3, 0.7, 0.2)};
  const VolumeFill f = fill_volume(m, false, l, 1.0);
  const Eigen::Vector3d n = lattice_counts(m, l);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY);
  for (const auto& v : m.vertices) lo = lo.cwiseMin(v);
  std::size_t brute = 0;
  for (int i = 0; i < int(n.x()); ++i)
    for (int j = 0; j < int(n.y()); ++j)
      for (int k = 0; k < int(n.z()); ++k)
        brute += winding_number(m, lo + l.spacing * (Eigen::Vector3d(i, j, k) + l.offset)) >= 0.5;
  EXPECT_EQ(f.cloud.size(), brute);
}

}  // namespace
}  // namespace tumble
