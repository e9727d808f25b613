#include "core/mass_properties.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <sstream>

#include <Eigen/Eigenvalues>

#include "core/error.hpp"

namespace tumble {

Eigen::Matrix3d inertia_about(const ParticleCloud& cloud, const Eigen::Vector3d& origin) {
  // -[r]×[r]× = |r|² I - r rᵀ (seed §6, with erratum 2: the tensor is symmetric).
  Eigen::Matrix3d j = Eigen::Matrix3d::Zero();
  for (const Particle& p : cloud) {
    const Eigen::Vector3d r = p.position - origin;
    j += p.mass * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
  }
  return j;
}

namespace {

[[noreturn]] void fail(const std::string& body, const std::string& why) {
  throw DegenerateBody("body '" + body + "': " + why);
}

// Eigenvector signs are arbitrary; fix them so the frame is deterministic:
// the largest-magnitude component of axes 1 and 2 is positive, axis 3 = 1 × 2.
Eigen::Matrix3d canonical_right_handed(Eigen::Matrix3d a) {
  for (int k = 0; k < 2; ++k) {
    Eigen::Index i;
    a.col(k).cwiseAbs().maxCoeff(&i);
    if (a(i, k) < 0) a.col(k) = -a.col(k);
  }
  a.col(2) = a.col(0).cross(a.col(1)).normalized();
  return a;
}

}  // namespace

namespace {

// Total mass and centre of mass; every mass finite and > 0, every coordinate finite.
void add_up_mass(const ParticleCloud& cloud, const std::string& body_name, MassProperties& mp) {
  Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < cloud.size(); ++i) {
    const Particle& p = cloud[i];
    if (!std::isfinite(p.mass) || !(p.mass > 0.0)) {
      std::ostringstream s;
      s << "particle " << i << " has mass " << p.mass << " kg; every mass must be finite and > 0";
      fail(body_name, s.str());
    }
    if (!p.position.allFinite()) fail(body_name, "particle " + std::to_string(i) + " has a non-finite coordinate");
    mp.mass += p.mass;
    weighted += p.mass * p.position;
  }
  mp.com = weighted / mp.mass;
}

// Finite inputs can still overflow: |r|² m beyond ~1e308 (e.g. coordinates of
// 1e160 m). Say so instead of letting NaN reach the eigen-solver.
void refuse_overflow(const ParticleCloud& cloud, const std::string& body_name, const MassProperties& mp) {
  if (std::isfinite(mp.mass) && mp.com.allFinite() && mp.inertia.allFinite()) return;
  double rmax = 0;
  for (const Particle& p : cloud) rmax = std::max(rmax, p.position.cwiseAbs().maxCoeff());
  std::ostringstream s;
  s << "the mass or inertia overflows double precision (total mass " << mp.mass << " kg, coordinates up to "
    << rmax << " m); express the body in smaller units (e.g. km and t instead of m and kg)";
  fail(body_name, s.str());
}

// A body with no rotational inertia about some axis (a point, a line, or
// moments outside the normal double range) is refused with the fix.
void refuse_degenerate(const ParticleCloud& cloud, const std::string& body_name, const MassProperties& mp) {
  const double largest = mp.principal_moments[2];
  if (cloud.size() == 1)
    fail(body_name, "a single point mass has no rotational inertia; use at least three non-collinear particles");
  if (!(largest > 0.0)) {
    bool same = true;
    for (const Particle& p : cloud) same = same && p.position == cloud[0].position;
    fail(body_name, same ? "all " + std::to_string(cloud.size()) +
                               " particles are at the same point, which has no rotational inertia; spread them "
                               "out (at least three non-collinear particles)"
                         : "the body is so small that its inertia underflows to zero; express it in larger "
                           "units (e.g. mm instead of m)");
  }
  if (mp.principal_moments[0] < kMinMomentRatio * largest)
    fail(body_name, "all particles are (nearly) collinear, so the moment about that line vanishes "
                    "(smallest/largest principal moment < 1e-12); give the rod a thickness, e.g. a box "
                    "shape with a non-zero cross-section");
  // Subnormal masses or moments (a particle of 1e-310 kg) lose their precision
  // and their inverses overflow: NaN a few steps in. Refuse them here.
  const double small = mp.principal_moments[0];
  if (!(mp.mass >= DBL_MIN) || !(small >= DBL_MIN)) {
    std::ostringstream s;
    s << "the total mass (" << mp.mass << " kg) or the smallest principal moment (" << small
      << " kg·m²) is below the normal double range (2.2e-308); express the body in larger units (e.g. g and mm)";
    fail(body_name, s.str());
  }
}

// The bounding box in the principal frame (about the centre of mass).
void principal_box(const ParticleCloud& cloud, MassProperties& mp) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  for (const Particle& p : cloud) {
    const Eigen::Vector3d r = mp.principal_axes.transpose() * (p.position - mp.com);
    lo = lo.cwiseMin(r);
    hi = hi.cwiseMax(r);
  }
  mp.box.center = 0.5 * (lo + hi);
  mp.box.half_extents = 0.5 * (hi - lo);
}

}  // namespace

MassProperties compute_mass_properties(const ParticleCloud& cloud, const std::string& body_name) {
  if (cloud.empty()) fail(body_name, "the particle cloud is empty; give `particles`, a `shape` or a `cloud` file");
  MassProperties mp;
  add_up_mass(cloud, body_name, mp);
  mp.inertia = inertia_about(cloud, mp.com);
  refuse_overflow(cloud, body_name, mp);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(mp.inertia);
  mp.principal_moments = eig.eigenvalues();  // ascending
  refuse_degenerate(cloud, body_name, mp);
  mp.principal_axes = canonical_right_handed(eig.eigenvectors());
  principal_box(cloud, mp);
  return mp;
}

}  // namespace tumble
