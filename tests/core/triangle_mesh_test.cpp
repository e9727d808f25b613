// Exact polyhedral mass properties (Eberly 2002) against closed forms, and the mesh check.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "core/triangle_mesh.hpp"
#include "mesh_shapes.hpp"

namespace tumble {
namespace {

using test::box_mesh;
using test::icosphere;
using test::tetra_mesh;

double rel(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) { return (a - b).norm() / b.norm(); }

TEST(PolyhedralMass, BoxEqualsClosedForm) {
  const Eigen::Vector3d size(0.3, 1.7, 0.9), centre(2.0, -1.0, 0.5);
  TriangleMesh m = box_mesh(size, centre);
  // Turn it off the axes: the closed form is R diag(...) Rᵀ.
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  for (auto& v : m.vertices) v = R * v;
  const SolidProperties s = solid_properties(m);
  const double V = size.prod(), M = 5.0;
  EXPECT_NEAR(s.volume, V, 1e-12 * V);
  EXPECT_LT((s.centroid - R * centre).norm(), 1e-12);
  const Eigen::Vector3d sq = size.cwiseAbs2();
  const Eigen::Matrix3d D = (M / 12 * Eigen::Vector3d(sq.y() + sq.z(), sq.x() + sq.z(), sq.x() + sq.y())).asDiagonal();
  EXPECT_LT(rel(s.inertia_for_mass(M), R * D * R.transpose()), 1e-12);
}

// ∫ r rᵀ dV = V/20 (Σ vᵢvᵢᵀ + s sᵀ), s = Σ vᵢ (the tetrahedron's covariance, Tonon 2004).
TEST(PolyhedralMass, TetrahedronEqualsClosedForm) {
  const Eigen::Vector3d v[4] = {{0.1, -0.2, 0.3}, {1.3, 0.2, -0.1}, {-0.4, 1.1, 0.5}, {0.2, 0.3, 1.6}};
  const TriangleMesh m = tetra_mesh(v[0], v[1], v[2], v[3]);
  const double V = std::abs((v[1] - v[0]).cross(v[2] - v[0]).dot(v[3] - v[0])) / 6;
  Eigen::Vector3d s = Eigen::Vector3d::Zero();
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  for (const auto& p : v) s += p, C += p * p.transpose();
  C = V / 20 * (C + s * s.transpose());
  const Eigen::Vector3d g = s / 4;
  const Eigen::Matrix3d Cc = C - V * g * g.transpose();  // about the centroid
  const Eigen::Matrix3d J = Cc.trace() * Eigen::Matrix3d::Identity() - Cc;

  const SolidProperties p = solid_properties(m);
  EXPECT_NEAR(p.volume, V, 1e-12 * V);
  EXPECT_LT((p.centroid - g).norm(), 1e-12);
  EXPECT_LT(rel(p.inertia, J), 1e-12);
}

// Inscribed polyhedra: volume and moments approach the sphere's from below as O(h²).
TEST(PolyhedralMass, IcosphereConvergesToSphere) {
  const double r = 0.8, V = 4.0 / 3 * std::numbers::pi * r * r * r, M = 2.0;
  double prev = 1;
  for (int level = 1; level <= 5; ++level) {
    const SolidProperties s = solid_properties(icosphere(level, r));
    const double ev = (V - s.volume) / V;
    EXPECT_GT(ev, 0) << "an inscribed polyhedron is smaller";
    EXPECT_LT(s.centroid.norm(), 1e-12);
    const Eigen::Matrix3d J = s.inertia_for_mass(M);
    const Eigen::Matrix3d sphere = 0.4 * M * r * r * Eigen::Matrix3d::Identity();
    const double ej = rel(J, sphere);
    if (level > 1) {
      EXPECT_NEAR(prev / ev, 4.0, 0.4) << "level " << level;  // h halves, error / 4
    }
    EXPECT_LT(ej, 2 * ev);
    prev = ev;
  }
  EXPECT_LT(prev, 1e-3);
}

TEST(PolyhedralMass, SignedVolumeFollowsOrientation) {
  TriangleMesh m = box_mesh({1, 2, 3});
  EXPECT_NEAR(inspect_mesh(m).signed_volume, 6.0, 1e-12);
  flip_orientation(m);
  const MeshReport r = inspect_mesh(m);
  EXPECT_NEAR(r.signed_volume, -6.0, 1e-12);
  EXPECT_TRUE(r.watertight()) << "consistently inverted is still closed";
  const SolidProperties s = solid_properties(m);
  EXPECT_NEAR(s.volume, -6.0, 1e-12);
  // The tensor per unit mass does not depend on the orientation.
  EXPECT_LT(rel(s.inertia_for_mass(1), solid_properties(box_mesh({1, 2, 3})).inertia_for_mass(1)), 1e-12);
}

TEST(MeshReport, FindsHolesFlipsAndDegenerateFaces) {
  TriangleMesh m = box_mesh({1, 1, 1});
  MeshReport r = inspect_mesh(m);
  EXPECT_EQ(r.triangles, 12u);
  EXPECT_TRUE(r.watertight());
  EXPECT_EQ(r.degenerate_faces, 0u);
  EXPECT_NEAR(r.area, 6.0, 1e-12);
  EXPECT_EQ(r.box_min, Eigen::Vector3d::Constant(-0.5));

  TriangleMesh holed = m;
  holed.triangles.pop_back();
  r = inspect_mesh(holed);
  EXPECT_FALSE(r.watertight());
  EXPECT_EQ(r.boundary_edges, 3u);

  TriangleMesh one_flipped = m;
  std::swap(one_flipped.triangles[0][1], one_flipped.triangles[0][2]);
  r = inspect_mesh(one_flipped);
  EXPECT_FALSE(r.watertight());
  EXPECT_EQ(r.misoriented_edges, 3u);

  TriangleMesh sliver = m;
  sliver.triangles.push_back({0, 1, 1});
  sliver.triangles.push_back({0, 1, 0});
  r = inspect_mesh(sliver);
  EXPECT_EQ(r.degenerate_faces, 2u);
  EXPECT_EQ(remove_degenerate_triangles(sliver), 2u);
  EXPECT_TRUE(inspect_mesh(sliver).watertight());
}

}  // namespace
}  // namespace tumble
