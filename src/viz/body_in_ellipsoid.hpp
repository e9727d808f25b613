// The body drawn inside its own inertia ellipsoid (Poinsot's figure): the
// ellipsoid is the body's, and a student sees whose by seeing the body in it,
// turned with it. GL-free: draw-list surfaces.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "viz/body_look.hpp"
#include "viz/draw_list.hpp"

namespace tumble::viz {

/// Name of the surfaces add_body_in_ellipsoid adds (inside the ellipsoid: a label may lie on them as on it).
inline constexpr const char* kEllipsoidBodyName = "ellipsoid_body";
/// How far out the body's principal box reaches: its farthest corner at this fraction of the ellipsoid.
inline constexpr double kEllipsoidBodyFill = 0.92;

/// The scale (view units per metre) that puts the box `centre` ± `half` (principal axes, m, about the
/// centre of mass) inside the ellipsoid of semi-axes sqrt(I₁/I_i) (build_poinsot's units: the largest 1),
/// its farthest corner at kEllipsoidBodyFill of the way out.
double ellipsoid_body_scale(const Eigen::Vector3d& inertia, const Eigen::Vector3d& centre, const Eigen::Vector3d& half);

/// Adds `look`'s surfaces, translucent (`alpha`) in their own colours, turned by `q` (world ← principal)
/// about the ellipsoid's centre (the view's origin) and scaled by ellipsoid_body_scale, in front of the
/// view's surfaces so that the ellipsoid's glass is drawn over them. `cloud_from_principal` and `com`
/// place the surfaces (cloud axes) in the principal frame. Nothing without surfaces.
void add_body_in_ellipsoid(View& view, const BodyLook& look, const Eigen::Quaterniond& q,
                           const Eigen::Quaterniond& cloud_from_principal, const Eigen::Vector3d& com,
                           const Eigen::Vector3d& inertia, float alpha);

}  // namespace tumble::viz
