// The momentum sphere (principal frame): for a torque-free body Π = Rᵀ L keeps
// |Π| = |L| (the sphere) and Σ Π_i²/I_i = 2E (the energy ellipsoid), so Π runs
// along their intersection, a polhode. Levels between the I1 and I3 extremes
// circle the axes of the smallest and largest moment; the level 2E = |L|²/I2
// is the separatrix: two great circles through ±e2, the intermediate axis.
// (Landau & Lifshitz, Mechanics §37; Goldstein, Classical Mechanics §5.6.)
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "viz/draw_list.hpp"
#include "viz/key.hpp"
#include "viz/sphere_camera.hpp"
#include "viz/sphere_reveal.hpp"

namespace tumble::viz {

/// Closed polhode curves on |Π| = `L` with Σ Π_i²/I_i = `two_E` (kg·m²/s, J),
/// principal frame, I1 ≤ I2 ≤ I3; `n` points each (first = last). Empty when
/// the level is outside [L²/I3, L²/I1]; at the separatrix level (|L|²/I2
/// within 1e-12 relative) the four half great circles through ±e2.
std::vector<std::vector<Eigen::Vector3d>> polhodes(const Eigen::Vector3d& inertia, double L, double two_E, int n);

/// The separatrix: both great circles Π3 = ±k Π1, k² = (1/I1 - 1/I2)/(1/I2 - 1/I3), radius L.
std::vector<std::vector<Eigen::Vector3d>> separatrix(const Eigen::Vector3d& inertia, double L, int n);

/// The branch of the level through `pi` that Π follows (its polhode): of the
/// two closed curves about ±e₁ (or ±e₃), the one on Π's side; empty on the
/// separatrix itself. Principal frame, `n` points (first = last).
std::vector<Eigen::Vector3d> own_polhode(const Eigen::Vector3d& inertia, const Eigen::Vector3d& pi, int n);

/// The energy ellipsoid is drawn only if its largest semi-axis is within this many |L|.
inline constexpr double kEnergyEllipsoidReach = 1.3;
/// Its opacity: a veil over the sphere, in its own colour.
inline constexpr float kEnergyEllipsoidAlpha = 0.28f;

/// One of several Π paths on one sphere (a comparison: each method's), oldest first, in its colour.
struct SphereTrack {
  std::vector<Eigen::Vector3d> path;  ///< Π (principal frame), kg·m²/s; the last is Π now
  Color color;
  float width = 1;                    ///< times the view's path width (a wide track under a narrow one shows both)
  std::string name;                   ///< the key's text
  std::string key;                    ///< else the key's text; tracks of one key text share one entry
  /// Its path named "polhode <name>" (reported, and kept clear of labels, as a curve a viewer
  /// follows); false for paths drawn over a reported one. The dots are not named: several at a
  /// saddle would crowd the axes' names off their tips.
  bool reported = true;
};

/// What the momentum-sphere view draws for one body.
struct MomentumSphereInput {
  Eigen::Vector3d inertia;                  ///< principal moments, ascending, kg·m²
  Eigen::Vector3d momentum = Eigen::Vector3d::Zero();  ///< Π now (principal frame), kg·m²/s
  std::vector<Eigen::Vector3d> history;     ///< past Π, oldest first
  double two_E = 0;                         ///< 2 × rotational energy, J
  SpherePose pose = {};                     ///< the camera's followed direction now (follow_track)
  SphereCameraSettings camera = {};
  bool energy_ellipsoid = true;             ///< the translucent energy ellipsoid (it meets the sphere on the polhode), when it fits
  float ellipsoid_alpha = kEnergyEllipsoidAlpha;  ///< its opacity (0: not drawn, e.g. before it fades in)
  float width_px = 640, height_px = 360;    ///< the viewport
  /// > 0: the camera's field of view shows a ball of this radius (|L|) whole in the viewport.
  double fit_radius = 0;
  int frame_h = 360;                        ///< the frame's height (text sizes)
  double text_scale = 1;                    ///< the scene's text scale ([draw] text_scale)
  bool trail = false;                       ///< Π's path drawn as `history` (from t = 0), not its whole polhode
  bool faint_polhode = false;               ///< with `trail`: Π's whole polhode kept, faint, under the path so far
  float line_scale = 1;                     ///< the curves' widths and Π's dot, times this
  int levels = 10;                          ///< other energies: the levels between L²/I3 and L²/I1 in this many steps
  bool level_arrows = true;                 ///< each other level's direction arrow (and the key's promise of it)
  float dot_scale = 1;                      ///< Π's dot radius, times this (on top of line_scale)
  bool dark_levels = false;                 ///< the other levels dark grey and opaque, wider, arrows larger: read from afar
  bool path_on_top = false;                 ///< Π's trail over the separatrix (default under it: the separatrix reads across it)
  /// What lies behind the ball not drawn at all (default: faint through it), and the axes
  /// named clear of the curves on the front, which are then all a viewer follows.
  bool hide_far_side = false;
  SphereReveal reveal = {};                 ///< what a build-up shows so far (the ellipsoid: energy_ellipsoid, ellipsoid_alpha)
  /// Several paths on the one sphere (the same body stepped by several methods), drawn in this
  /// order, each ended by its dot, instead of `history` and Π's own dot (`momentum` still sets |L|).
  std::vector<SphereTrack> tracks = {};
  bool tracks_under_separatrix = false;     ///< the tracks' paths under the separatrix's dashes (their dots over all)
};

/// The energy ellipsoid Σ Π_i²/I_i = `two_E` in units of |Π| = `L` (so the
/// sphere has radius 1), principal frame: only its parts outside the sphere
/// (what the opaque ball does not hide), whose edges are the polhodes, where
/// it meets the sphere. Translucent, in its own colour (Meaning::energy_ellipsoid).
SurfaceItem energy_ellipsoid(const Eigen::Vector3d& inertia, double L, double two_E);

/// Whether the view of `in` draws the energy ellipsoid: asked for, and its
/// largest semi-axis within kEnergyEllipsoidReach.
bool draws_energy_ellipsoid(const MomentumSphereInput& in);

/// The momentum sphere's key entries: what the view of `in` draws, no more
/// (no energy ellipsoid where it is too large to draw).
std::vector<KeyEntry> sphere_key(const MomentumSphereInput& in);

/// Radius of the opaque ball inside the sphere that hides the far side, in |L|.
inline constexpr double kSphereBall = 0.985;
/// The ball's colour (lit); what shows through it is drawn part way to it.
inline constexpr Color kSphereBallColor{0.93f, 0.94f, 0.97f, 1.0f};

/// Fills `view` (camera included): drawn in units of |L| (sphere of radius 1).
/// The Π dot is the point named "momentum_point"; e₁, e₂, e₃ label the axes'
/// tips that the ball does not hide.
void build_momentum_sphere(View& view, const MomentumSphereInput& in);

}  // namespace tumble::viz
