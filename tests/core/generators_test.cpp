// Shape generators converge to the solid bodies' inertia as the lattice refines.
#include <gtest/gtest.h>

#include <cmath>

#include "base/error.hpp"
#include "core/mass_properties.hpp"
#include "core/particle_cloud.hpp"

namespace tumble {
namespace {

double rel_err(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return (a - b).cwiseQuotient(b).cwiseAbs().maxCoeff();
}

double total_mass(const ParticleCloud& c) {
  double m = 0;
  for (const Particle& p : c) m += p.mass;
  return m;
}

// Solid ellipsoid: J = M/5 (b² + c², a² + c², a² + b²).
TEST(Generators, EllipsoidConvergesToSolid) {
  const Eigen::Vector3d ax(1.0, 0.6, 0.3);
  const double M = 3.0;
  const Eigen::Vector3d solid = M / 5 * Eigen::Vector3d(ax.y() * ax.y() + ax.z() * ax.z(),
                                                       ax.x() * ax.x() + ax.z() * ax.z(),
                                                       ax.x() * ax.x() + ax.y() * ax.y());
  double e_coarse = 0, e_fine = 0;
  for (int n : {10, 80}) {
    const ParticleCloud c = make_ellipsoid(ax, n, M);
    EXPECT_NEAR(total_mass(c), M, 1e-15 * M * c.size());  // summation round-off
    const MassProperties mp = compute_mass_properties(c, "ellipsoid");
    EXPECT_LT(mp.com.norm(), 1e-12);
    const double e = rel_err(mp.inertia.diagonal(), solid);
    (n == 10 ? e_coarse : e_fine) = e;
  }
  EXPECT_LT(e_fine, e_coarse);
  EXPECT_LT(e_fine, 0.02);  // surface error O(1/n)
}

// Solid cylinder along z: J_zz = M r²/2, J_xx = J_yy = M(3r² + L²)/12.
TEST(Generators, CylinderConvergesToSolid) {
  const double r = 0.4, L = 2.0, M = 1.5;
  const Eigen::Vector3d solid(M * (3 * r * r + L * L) / 12, M * (3 * r * r + L * L) / 12, M * r * r / 2);
  double e_coarse = 0, e_fine = 0;
  for (int n : {8, 64}) {
    const ParticleCloud c = make_cylinder(r, L, n, M);
    EXPECT_NEAR(total_mass(c), M, 1e-15 * M * c.size());  // summation round-off
    const MassProperties mp = compute_mass_properties(c, "cylinder");
    const double e = rel_err(mp.inertia.diagonal(), solid);
    (n == 8 ? e_coarse : e_fine) = e;
  }
  EXPECT_LT(e_fine, e_coarse);
  EXPECT_LT(e_fine, 0.02);
}

// T-handle = two solid boxes: handle (Lh × t × t) centred at the origin, stem
// (t × Ls × t) from y = t/2 to t/2 + Ls, masses by volume; then shifted so the
// bounding box is centred. Composite inertia about the common centre of mass by
// the parallel-axis theorem.
TEST(Generators, THandleConvergesToTwoSolidBoxes) {
  const double Lh = 0.8, Ls = 0.6, t = 0.1, M = 2.0;
  const double vh = Lh * t * t, vs = Ls * t * t, mh = M * vh / (vh + vs), ms = M - mh;
  const double yh = 0.0, ys = t / 2 + Ls / 2;
  const double yc = (mh * yh + ms * ys) / M;
  auto box = [](double m, const Eigen::Vector3d& s) {
    return Eigen::Vector3d(m * (s.y() * s.y() + s.z() * s.z()) / 12, m * (s.x() * s.x() + s.z() * s.z()) / 12,
                           m * (s.x() * s.x() + s.y() * s.y()) / 12);
  };
  Eigen::Vector3d J = box(mh, {Lh, t, t}) + box(ms, {t, Ls, t});
  // Offsets along y only: J_xx and J_zz gain m d².
  for (auto [m, y] : {std::pair{mh, yh}, std::pair{ms, ys}}) {
    J.x() += m * (y - yc) * (y - yc);
    J.z() += m * (y - yc) * (y - yc);
  }
  const double y_mid = Ls / 2;  // centre of the bounding box y ∈ [-t/2, t/2 + Ls]
  double prev = INFINITY;
  for (int per_metre : {50, 100, 200}) {
    const ParticleCloud c = make_t_handle(Lh, Ls, t, per_metre, M);
    EXPECT_NEAR(total_mass(c), M, 1e-15 * M * c.size());  // summation round-off
    const MassProperties mp = compute_mass_properties(c, "t_handle");
    EXPECT_NEAR(mp.com.y(), yc - y_mid, 1e-12) << per_metre;
    EXPECT_LT(mp.inertia(0, 1), 1e-12);
    const double e = rel_err(mp.inertia.diagonal(), J);
    EXPECT_LT(e, prev) << per_metre;
    prev = e;
  }
  EXPECT_LT(prev, 0.01);
}

TEST(Generators, RejectNonsenseParameters) {
  EXPECT_THROW(make_box({1, 0, 1}, {2, 2, 2}, 1.0), InputError);
  EXPECT_THROW(make_box({1, 1, 1}, {2, 0, 2}, 1.0), InputError);
  EXPECT_THROW(make_box({1, 1, 1}, {2, 2, 2}, -1.0), InputError);
  EXPECT_THROW(make_ellipsoid({1, 1, NAN}, 10, 1.0), InputError);
  EXPECT_THROW(make_cylinder(-1, 1, 10, 1.0), InputError);
  EXPECT_THROW(make_t_handle(1, 1, 0.1, 0, 1.0), InputError);
}

}  // namespace
}  // namespace tumble
