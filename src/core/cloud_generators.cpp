// Lattice generators. Particles sit at cell centres, so a box lattice's inertia
// is M(b²+c²)/12 · (1 - 1/n²)-like and converges to the solid value as n grows.
#include <algorithm>
#include <cmath>
#include <limits>

#include "base/error.hpp"
#include "core/particle_cloud.hpp"

namespace tumble {

namespace {

double cell_centre(int i, int n, double length) { return ((i + 0.5) / n - 0.5) * length; }

void require_positive(double v, const char* what) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw InputError(std::string(what) + " must be a finite number > 0");
}

void scale_mass(ParticleCloud& c, double mass) {
  if (c.empty()) return;
  const double m = mass / static_cast<double>(c.size());
  for (Particle& p : c) p.mass = m;
}

}  // namespace

ParticleCloud make_box(const Eigen::Vector3d& size, const Eigen::Vector3i& n, double mass) {
  for (int k = 0; k < 3; ++k) {
    require_positive(size[k], "box size");
    if (n[k] < 1) throw InputError("box lattice counts must be >= 1");
  }
  require_positive(mass, "mass");
  ParticleCloud c;
  c.reserve(static_cast<size_t>(n.x()) * n.y() * n.z());
  for (int i = 0; i < n.x(); ++i)
    for (int j = 0; j < n.y(); ++j)
      for (int k = 0; k < n.z(); ++k)
        c.push_back({{cell_centre(i, n.x(), size.x()), cell_centre(j, n.y(), size.y()),
                      cell_centre(k, n.z(), size.z())}, 0.0});
  scale_mass(c, mass);
  return c;
}

ParticleCloud make_ellipsoid(const Eigen::Vector3d& semi_axes, int n, double mass) {
  for (int k = 0; k < 3; ++k) require_positive(semi_axes[k], "ellipsoid semi-axis");
  require_positive(mass, "mass");
  if (n < 2) throw InputError("ellipsoid lattice count must be >= 2");
  ParticleCloud c;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        // Tested in the unit ball, then scaled: 2 × a semi-axis near the
        // largest double overflows (and the test on it lost every point).
        const Eigen::Vector3d u(cell_centre(i, n, 2.0), cell_centre(j, n, 2.0), cell_centre(k, n, 2.0));
        if (u.squaredNorm() <= 1.0) c.push_back({u.cwiseProduct(semi_axes), 0.0});
      }
  scale_mass(c, mass);
  return c;
}

ParticleCloud make_cylinder(double radius, double length, int n, double mass) {
  require_positive(radius, "cylinder radius");
  require_positive(length, "cylinder length");
  require_positive(mass, "mass");
  if (n < 2) throw InputError("cylinder lattice count must be >= 2");
  const int nz = std::max(1, static_cast<int>(std::lround(n * length / (2 * radius))));
  ParticleCloud c;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = cell_centre(i, n, 2.0), v = cell_centre(j, n, 2.0);  // unit disc, as the ellipsoid
      if (u * u + v * v > 1.0) continue;
      for (int k = 0; k < nz; ++k) c.push_back({{u * radius, v * radius, cell_centre(k, nz, length)}, 0.0});
    }
  scale_mass(c, mass);
  return c;
}

ParticleCloud make_t_handle(double handle_length, double stem_length, double thickness,
                            int per_metre, double mass) {
  require_positive(handle_length, "handle_length");
  require_positive(stem_length, "stem_length");
  require_positive(thickness, "thickness");
  require_positive(mass, "mass");
  if (per_metre < 1) throw InputError("t_handle resolution must be >= 1 particle per metre");
  auto count = [&](double len) { return std::max(1, static_cast<int>(std::lround(len * per_metre))); };
  const int nt = count(thickness);
  // Handle along x, centred at y = 0; stem along +y starting at the handle's edge.
  ParticleCloud handle = make_box({handle_length, thickness, thickness},
                                  {count(handle_length), nt, nt}, 1.0);
  ParticleCloud stem = make_box({thickness, stem_length, thickness}, {nt, count(stem_length), nt}, 1.0);
  // Masses in proportion to the volumes; for a handle so thin that the
  // volumes underflow (0/0 gave a NaN mass) their common factor thickness² is left out.
  const double v_handle = handle_length * thickness * thickness;
  const double v_stem = stem_length * thickness * thickness;
  const double m_handle = v_handle + v_stem >= std::numeric_limits<double>::min()
                              ? mass * v_handle / (v_handle + v_stem)
                              : mass * (handle_length / (handle_length + stem_length));
  for (Particle& p : handle) p.mass = m_handle / handle.size();
  for (Particle& p : stem) p.mass = (mass - m_handle) / stem.size();
  // Bounding box spans y in [-t/2, t/2 + stem]; centre it.
  const double y_mid = 0.5 * stem_length;
  ParticleCloud c;
  append_cloud(c, handle, {0.0, -y_mid, 0.0});
  append_cloud(c, stem, {0.0, 0.5 * thickness + 0.5 * stem_length - y_mid, 0.0});
  return c;
}

}  // namespace tumble
