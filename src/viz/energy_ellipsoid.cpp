// The energy ellipsoid Σ Π_i²/I_i = 2E as it shows outside the momentum
// sphere's opaque ball: only its parts outside |Π| = |L|, whose edges are the
// body's polhodes themselves (closed form), so it meets the drawn polhode
// exactly instead of along the ragged seam of two tessellated surfaces.
#include <cmath>
#include <numbers>

#include "viz/momentum_sphere.hpp"
#include "viz/sphere_figure.hpp"
#include "viz/surfaces.hpp"

namespace tumble::viz {

namespace {

constexpr int kRings = 24;

struct Grid {
  std::vector<std::vector<Eigen::Vector3d>> rows;  // rings × points, units of |L|
};

// Triangles of a ring grid (each row closed around), normals of the ellipsoid (∝ Π_i/I_i).
void add_grid(SurfaceMesh& m, const Grid& g, const Eigen::Vector3d& I) {
  auto put = [&](const Eigen::Vector3d& p) {
    const Eigen::Vector3d n = p.cwiseQuotient(I).normalized();
    m.positions.emplace_back(float(p.x()), float(p.y()), float(p.z()));
    m.normals.emplace_back(float(n.x()), float(n.y()), float(n.z()));
  };
  for (std::size_t j = 0; j + 1 < g.rows.size(); ++j)
    for (std::size_t k = 0; k + 1 < g.rows[j].size(); ++k) {
      put(g.rows[j][k]), put(g.rows[j + 1][k]), put(g.rows[j + 1][k + 1]);
      put(g.rows[j][k]), put(g.rows[j + 1][k + 1]), put(g.rows[j][k + 1]);
    }
}

}  // namespace

SurfaceItem energy_ellipsoid(const Eigen::Vector3d& I, double L, double two_E) {
  const double e = two_E / (L * L);  // the level in units of |L|: Σ p_i²/I_i = e, |p| = 1 on the polhode
  const Color colour = color_of(Meaning::energy_ellipsoid, kEnergyEllipsoidAlpha);
  auto mesh = std::make_shared<SurfaceMesh>();
  // Outside the sphere lie the caps about ±e3 (a polhode about e3: 2E < L²/I2) or the band
  // about e2 and e3 between the two polhodes about ±e1 (2E > L²/I2).
  const bool caps = e <= 1 / I[1];
  const int a = caps ? 2 : 0, b = caps ? 0 : 1, c = caps ? 1 : 2;
  const double rhs = e - 1 / I[a];
  const double sb = rhs / (1 / I[b] - 1 / I[a]), sc = rhs / (1 / I[c] - 1 / I[a]);
  if (!(sb >= 0 && sc >= 0)) return {mesh, glm::dmat4(1.0), colour};
  // The polhode's own parameter, refined where it bends (as polhodes() draws it).
  auto rim = [&](double phi) {
    Eigen::Vector3d p;
    p[b] = std::sqrt(sb) * std::cos(phi), p[c] = std::sqrt(sc) * std::sin(phi);
    p[a] = std::sqrt(std::max(0.0, 1 - p[b] * p[b] - p[c] * p[c]));
    return p;
  };
  std::vector<double> start;
  for (int i = 0; i <= 128; ++i) start.push_back(2 * std::numbers::pi * i / 128);
  const std::vector<double> phis = refined_params(rim, start, 1e-3);
  auto on_ellipsoid = [&](double along_a, const Eigen::Vector3d& across) {  // p_a given, (p_b, p_c) ∝ across
    const double room = std::max(0.0, e - along_a * along_a / I[a]);
    const double lambda = std::sqrt(room / (across[b] * across[b] / I[b] + across[c] * across[c] / I[c]));
    Eigen::Vector3d q = lambda * across;
    q[a] = along_a;
    return q;
  };
  Grid g;
  for (int j = 0; j <= kRings; ++j) {
    std::vector<Eigen::Vector3d> row;
    for (double phi : phis) {
      Eigen::Vector3d p = rim(phi);
      if (caps) {  // from the polhode (j = 0) up to the pole of e3 (j = kRings): p_a grows
        const double top = std::sqrt(e * I[a]);
        const double pa = p[a] + (top - p[a]) * j / kRings;
        Eigen::Vector3d across = p;
        across[a] = 0;
        row.push_back(on_ellipsoid(pa, across));
      } else {  // from the polhode about +e1 (j = 0) to the one about −e1 (j = kRings)
        const double pa = p[a] * (1 - 2.0 * j / kRings);
        Eigen::Vector3d across = p;
        across[a] = 0;
        row.push_back(on_ellipsoid(pa, across));
      }
    }
    g.rows.push_back(std::move(row));
  }
  add_grid(*mesh, g, I);
  if (caps) {  // the other cap, about −e3
    for (auto& row : g.rows)
      for (Eigen::Vector3d& p : row) p[a] = -p[a];
    add_grid(*mesh, g, I);
  }
  return {mesh, glm::dmat4(1.0), colour};  // unnamed: a key may cover its caps (keep_clear), never the sphere
}

}  // namespace tumble::viz
