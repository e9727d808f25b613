// The momentum sphere drawn as a textbook figure: curves in closed form,
// refined where they bend; ±e₁, ±e₂, ±e₃ labelled at every end that can be
// seen; the saddles ±e₂ marked; arrows along the level curves giving the
// direction of motion (dΠ/dt = Π × ω, ω = I⁻¹Π); and the far side of what a
// viewer follows (polhode, Π, saddles) shown faintly through the ball, as a
// textbook draws a sphere's hidden half (or, asked, not at all); the
// separatrix's far half not drawn. GL-free.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "viz/draw_list.hpp"

namespace tumble::viz {

/// The curve `at` (parameter → point) through `params` (ascending), each
/// interval halved until the curve's midpoint is within `tolerance` of the
/// chord's and the chord within 30 `tolerance` long (at most 2¹⁰ pieces an interval).
std::vector<Eigen::Vector3d> refined_curve(const std::function<Eigen::Vector3d(double)>& at,
                                           const std::vector<double>& params, double tolerance);

/// The parameters refined_curve would draw `at` at.
std::vector<double> refined_params(const std::function<Eigen::Vector3d(double)>& at, const std::vector<double>& params,
                                   double tolerance);

/// The axes' ends, |L| from the centre, and how far out their labels reach (about).
inline constexpr double kAxisReach = 1.22, kAxisLabelReach = 1.37;

/// Adds the axes through the sphere (+e_i arrows, −e_i lines) and a label at
/// each end the ball does not hide ("e₁" named axis_label_e1, "−e₁" named
/// axis_label_-e1, ...): just past its own tip on screen, along the axis as
/// drawn (up and right of an end pointing at the camera), turned until it is
/// clear of the six half-axes. An end behind the ball is not named.
void add_sphere_axes(View& view, float width_px, float height_px, float label_px);

/// The unit ball (centre at the origin) as `camera` draws it in a `width_px` × `height_px`
/// view: centre x, y and radius in px; none where it cannot be projected.
std::optional<glm::vec3> ball_on_screen(const Camera& camera, float width_px, float height_px);

/// add_sphere_axes in two steps: the axes, then their names; `clear_of_curves`:
/// the names also kept clear of the named curves drawn by then (those a viewer
/// follows) where the ball does not hide them.
void add_sphere_axis_lines(View& view);
void name_sphere_axes(View& view, float width_px, float height_px, float label_px, bool clear_of_curves = false);

/// The saddles ±e₂ (points named saddle_+e2, saddle_-e2) on the unit sphere.
void add_saddles(View& view);

/// Small arrows along `curve` (units of |L|, closed) in the direction Π moves,
/// `count` of them spread along its length; none where the ball hides them.
void add_direction_arrows(View& view, const std::vector<Eigen::Vector3d>& curve, const Eigen::Vector3d& inertia,
                          int count, Color color, double size);

/// How a marker (a point) behind the ball is drawn: its colour two thirds of
/// the way to the ball's, opaque (points are drawn as opaque lit balls).
Color faint_marker(Color c);

/// The far-side parts of polylines [`first`, end) and of the named points of
/// `view` (units of |L|): brought along the eye's rays to the ball's near side
/// (same pixels) and drawn faint (points: faint_marker), so they show through it; the far runs of
/// the separatrix are dropped (through the ball they read as a ring round a pole).
/// `hide`: all of them dropped instead, markers too (faint, they read as on the front face);
/// a kept run reaches behind the ball by its end points at most (the ball hides those).
void show_far_side(View& view, std::size_t first_polyline, double ball, bool hide = false);

}  // namespace tumble::viz
