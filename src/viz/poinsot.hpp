// Poinsot's construction (Goldstein, Classical Mechanics §5.6; Landau &
// Lifshitz, Mechanics §37). In ω-space the body-fixed ellipsoid
// ωᵀ J ω = 2E (J = R J0 Rᵀ, the world inertia) holds ω's tip. Its normal
// there is ∇(ωᵀJω) = 2Jω = 2L, fixed in space, and the tip's distance along L̂
// is ω·L/|L| = 2E/|L|, constant: the ellipsoid touches the fixed invariable
// plane {x : x·L̂ = 2E/|L|} at ω's tip and, as the contact point is on the
// instantaneous axis (at rest), rolls on it without slipping. The tip traces
// the polhode on the ellipsoid and the herpolhode on the plane.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "viz/draw_list.hpp"
#include "viz/key.hpp"
#include "viz/sphere_camera.hpp"

namespace tumble::viz {

/// The construction at one instant, world frame, ω-space units (rad/s).
struct PoinsotGeometry {
  Eigen::Matrix3d axes;         ///< columns: the ellipsoid's axes (the body's principal axes, world)
  Eigen::Vector3d semi_axes;    ///< sqrt(2E / I_i), rad/s
  Eigen::Vector3d normal;       ///< L̂, the invariable plane's normal
  double plane_distance = 0;    ///< 2E/|L|, rad/s
  Eigen::Vector3d contact;      ///< ω_world: where the ellipsoid touches the plane
};

/// `q` = world ← principal, `inertia` ascending (kg·m²), `L` world (kg·m²/s).
PoinsotGeometry poinsot_geometry(const Eigen::Quaterniond& q, const Eigen::Vector3d& inertia, const Eigen::Vector3d& L);

struct PoinsotInput {
  Eigen::Quaterniond q;                 ///< world ← principal, now
  Eigen::Vector3d inertia;              ///< ascending, kg·m²
  Eigen::Vector3d L;                    ///< world, kg·m²/s
  std::vector<Eigen::Vector3d> omega_principal_history;  ///< ω in the principal frame, oldest first (polhode)
  std::vector<Eigen::Vector3d> omega_world_history;      ///< ω in the world, oldest first (herpolhode)
  /// Azimuth (in the plane, from its first basis vector), elevation (above the
  /// plane's far side) and distance (largest semi-axes) of the camera; follow is
  /// unused. By default 40° above the plane, so the herpolhode opens up.
  SphereCameraSettings camera = {16.4, 39.8, 4.69, false, 0, 0};
  float width_px = 640, height_px = 360;    ///< the viewport
  int frame_h = 360;                        ///< the frame's height (text sizes)
  double text_scale = 1;                    ///< the scene's text scale ([draw] text_scale)
  /// The separatrix on the ellipsoid, dashed: the polhodes through ±e₂ (|L|² = 2E·I₂),
  /// which part the loops round e₁ from those round e₃.
  bool separatrix = false;
  /// The contact region alone, the camera aimed at the foot of L: the curves,
  /// the contact point and the polhode's start; no arrows, no separatrix, no names.
  bool close_up = false;
  /// The plane named (false: a close-up below the view shows it, its title naming it; no room is left here).
  bool name_plane = true;
  /// The dots' radius times this (a close-up's narrowed field keeps them their size on screen).
  double dot_scale = 1;
};

/// The plane's surface: opaque and light, so the palette's curves show on it
/// (its grid and key swatch use the palette's plane grey).
inline constexpr Color kPlaneColor{0.84f, 0.85f, 0.88f, 1.0f};
/// The herpolhode is drawn this far (scaled ω units) off the opaque plane,
/// towards the ellipsoid, so the plane's depth does not hide it.
inline constexpr double kHerpolhodeLift = 0.008;

/// The contact point's dot (ω's tip), in units of the largest semi-axis: about
/// 2 % of a view's height, the eye's first stop in the construction.
inline constexpr double kContactDotRadius = 0.065;

/// Fills `view` (camera included); ω-space scaled so the ellipsoid's largest semi-axis is 1.
/// The ellipsoid is a shaded translucent surface resting on an opaque plane
/// (its key, poinsot_key(), is the layout's to draw).
/// ω's tip is the point named "contact_point".
void build_poinsot(View& view, const PoinsotInput& in);

/// Poinsot's key entries (`separatrix`: with the dashed separatrix's).
std::vector<KeyEntry> poinsot_key(bool separatrix = false);

/// The separatrix on the inertia ellipsoid of energy `two_E` (J, ×2), principal
/// frame, ω-space (rad/s): the two closed curves ω = Π/I with Π on the separatrix
/// great circles of radius √(2E·I₂); `n` points each (first = last).
std::vector<std::vector<Eigen::Vector3d>> ellipsoid_separatrix(const Eigen::Vector3d& inertia, double two_E, int n);

}  // namespace tumble::viz
