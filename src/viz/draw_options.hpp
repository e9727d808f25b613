// What a view of bodies draws: viz owns these options; the scene reader
// (scene::DrawConfig, `[draw]`) and the command line fill them by name.
#pragma once

#include <array>
#include <optional>

namespace tumble::viz {

/// What to draw (scene `[draw]`, overridable on the command line).
struct DrawOptions {
  /// The principal box: unset = only for a body drawn without a surface
  /// (translucent, as the seed drew it); true = also around surfaces, as an outline.
  std::optional<bool> box;
  bool surface = true;       ///< generated shapes and meshes as their lit surfaces
  bool axes = true;          ///< principal axes: red = smallest moment, green, blue = largest
  bool particles = false;
  bool angular_momentum = false;  ///< world L as an arrow
  bool omega = false;             ///< ω_world as an arrow
  double trail_seconds = 0;       ///< trails of the axis tips over the last N s (0 = off)
  std::array<bool, 3> trail_axes = {true, true, true};  ///< which axes' tips leave a trail (e1, e2, e3)
  bool grid = false;
  double arrow_width = 1;         ///< the arrows' (axes, L, ω) thickness, times their usual
  double arrow_length = 1;        ///< L's and ω's length, times their usual (kLReach, kOmegaReach)
  double text_scale = 1;          ///< text sizes but the title card's and captions', times their usual (viz::text_px)
  bool tip_names_further = false; ///< a tip's name with no place beside its head may go a line or two further out
  bool angle_arc = false;         ///< with L and ω: an arc from L to ω at the body, the angle between them (viz/angle_arc.hpp)
};

}  // namespace tumble::viz
