#include "viz/body_in_ellipsoid.hpp"

#include <algorithm>
#include <cmath>

namespace tumble::viz {

double ellipsoid_body_scale(const Eigen::Vector3d& inertia, const Eigen::Vector3d& centre, const Eigen::Vector3d& half) {
  double reach = 0;  // the farthest corner, in units of the ellipsoid (1: on it) at one view unit per metre
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d p = centre + half.cwiseProduct(Eigen::Vector3d(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
    double s = 0;
    for (int a = 0; a < 3; ++a) s += p[a] * p[a] * inertia[a] / inertia[0];  // p_a² / (I₁/I_a)
    reach = std::max(reach, std::sqrt(s));
  }
  return reach > 0 ? kEllipsoidBodyFill / reach : 0;
}

void add_body_in_ellipsoid(View& view, const BodyLook& look, const Eigen::Quaterniond& q,
                           const Eigen::Quaterniond& cloud_from_principal, const Eigen::Vector3d& com,
                           const Eigen::Vector3d& inertia, float alpha) {
  if (look.surfaces.empty() || !look.surface_box) return;
  const double s = ellipsoid_body_scale(inertia, look.surface_box->first, look.surface_box->second);
  // world = s · q · (cloud ← principal)ᵀ · (p − com): the body's principal axes on the ellipsoid's.
  const Eigen::Matrix3d turn = s * (q * cloud_from_principal.conjugate()).toRotationMatrix();
  const Eigen::Vector3d shift = -turn * com;
  glm::dmat4 model(1.0);
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) model[c][r] = turn(r, c);
  model[3] = glm::dvec4(shift.x(), shift.y(), shift.z(), 1.0);
  std::vector<SurfaceItem> body;
  for (std::size_t i = 0; i < look.surfaces.size(); ++i) {
    Color c = i < look.surface_colors.size() ? look.surface_colors[i] : Color{0.7f, 0.7f, 0.7f, 1};
    c.a = alpha;
    body.push_back({look.surfaces[i], model, c, kEllipsoidBodyName});
  }
  view.surfaces.insert(view.surfaces.begin(), body.begin(), body.end());
}

}  // namespace tumble::viz
