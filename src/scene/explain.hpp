// Scene settings of explanatory videos: time mapping (time_scale,
// slow-motion segments), captions, a title card and laid-out views.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace tumble::scene {

/// Which parts of a readout line show ([draw] overlay, a world view's readout).
struct OverlayItems {
  bool time = true, method = true, step = true, energy = true;
  bool state = false;  ///< E, |L| and |ω| of the first body: only when asked for
  bool angle = false;  ///< ∠(ω, L) of the first body, degrees: only when asked for
  /// ∠(e₁, L), ∠(e₂, L), ∠(e₃, L) of the first body, degrees: how far a spin axis is from L (past 90°: turned over)
  bool e1_angle = false, e2_angle = false, e3_angle = false;
  bool any() const { return time || method || step || energy || state || angle || e1_angle || e2_angle || e3_angle; }
};

/// A stretch of simulated time played at its own speed.
struct SlowMotion {
  double start = 0, end = 0;  ///< simulated s
  double time_scale = 0.25;   ///< simulated s per video s inside [start, end]
};

/// Reading time a caption needs at video speed, s a word (about 200 words a
/// minute, read aloud with a pause for the picture).
inline constexpr double kSecondsPerWord = 0.3;

/// Where a caption sits: centred in a strip at the frame's bottom (default) or top.
enum class CaptionPosition { bottom, top };

/// Text shown while the simulated time is in [start, end], fading in and out.
/// A scene may anchor start/end to flips (scene/events.hpp): they are resolved
/// at load, and `start_text`/`end_text` keep what the file said.
struct Caption {
  double start = 0, end = 0;  ///< simulated s
  std::string text;
  std::string start_text, end_text;  ///< as written ("flip 1 - 0.2", "1.5")
  std::size_t body = 0;              ///< the body whose flips anchor it
  CaptionPosition position = CaptionPosition::bottom;
  /// Video s after the first frame showing `start` before it appears, and
  /// (> 0) how many video s it then stays up instead of until `end`: captions
  /// in turn during one hold (a figure built up step by step while t stands still).
  double after = 0, seconds = 0;
};

/// The animation stops for `hold` video s at simulated `at` (e.g. "flip 1"):
/// its frames all show t = at (FrameClock).
struct Hold {
  double at = 0;              ///< simulated s
  double hold = 2;            ///< video s
  std::string at_text;        ///< as written
  std::string label;          ///< why it stops, after "paused: " in the badge (empty: "paused")
};

/// A title card on its own backdrop for the first `hold` s of video, while the
/// animation waits at t = 0 (FrameClock).
struct TitleCard {
  std::string text, subtitle;
  double hold = 0;            ///< video s; 0 = no title
};

enum class ViewKind { world, body_frame, momentum_sphere, plot, poinsot };

/// A view's `camera = { azimuth, elevation, distance, follow }` (body_frame,
/// momentum_sphere, poinsot); unset fields keep the view kind's defaults.
struct ViewCamera {
  std::optional<double> azimuth_deg, elevation_deg;  ///< degrees
  std::optional<double> distance;  ///< body_frame: body sizes; momentum_sphere: |L|; poinsot: largest semi-axes
  std::optional<bool> follow;      ///< momentum_sphere: follow Π (default: a fixed textbook view); body_frame: turn with the body
  /// world and body_frame views: across = "L" (+1) or "-L" (−1) looks across
  /// L at t = 0, L up (down) in the picture plane (scene.hpp, CameraConfig)
  int across = 0;
  std::optional<double> roll_deg;  ///< world, across L: L turned clockwise in the picture (default 0: L up)
  /// world views only: as [camera] (m, world; degrees); `up` also a
  /// momentum_sphere's picture up, in principal axes (default +e₃), and a
  /// body_frame's: its camera then fixed in principal axes (azimuth, elevation as a sphere's)
  std::optional<std::array<double, 3>> position, target, up;
  std::optional<double> fov_y_deg;
};

/// One `[[views]]` table.
struct ViewConfig {
  ViewKind kind = ViewKind::world;
  /// x, y, width, height as fractions of the frame from its top-left corner; none = full frame.
  std::optional<std::array<double, 4>> viewport;
  std::string body;                 ///< body name; empty = the first body
  std::vector<std::string> series;  ///< plot: wbx wby wbz |w| energy_error axis1_L axis2_L axis3_L
  std::string title;                ///< drawn in the view's corner
  ViewCamera camera;
  bool energy_ellipsoid = true;     ///< momentum_sphere: the energy ellipsoid (when it fits)
  double ellipsoid_from = 0;        ///< momentum_sphere: simulated s from which the ellipsoid fades in (1 s of video)
  std::optional<double> ellipsoid_opacity;  ///< momentum_sphere: the ellipsoid's opacity; none = the figure's veil
  bool level_arrows = true;         ///< momentum_sphere: the other levels' direction arrows (false: a small sphere's, unseen)
  double zoom = 1;                  ///< momentum_sphere: the figure this much larger in its content (room kept for fewer labels)
  double dot_scale = 1;             ///< momentum_sphere: Π's dot radius times this (on top of line_scale)
  bool dark_levels = false;         ///< momentum_sphere: the other levels dark grey and opaque (read from afar), not faint
  bool path_on_top = false;         ///< momentum_sphere: Π's trail drawn over the dashed separatrix (a path a fraction of a degree off it)
  bool hide_far_side = false;       ///< momentum_sphere: what lies behind the ball not drawn (default: faint through it)
  bool separatrix = false;          ///< poinsot: the separatrix dashed on the inertia ellipsoid (the polhodes through ±e₂)
  /// poinsot: the contact region alone, close up (an inset): the polhode, the herpolhode and the contact point,
  /// no arrows, no body; its field narrowed to those curves over the whole run
  bool close_up = false;
  /// momentum_sphere: these bodies' Π from t = 0 on the one sphere, each scaled to it (Π/|L| of its own):
  /// bodies of one inertia compared on one figure; empty = the view's body's Π alone
  std::vector<std::string> paths_of;
  bool path_trail = false;          ///< momentum_sphere `path = "trail"`: Π's path so far, not its whole polhode
  bool path_faint_polhode = false;  ///< `path = "trail_on_polhode"`: the trail over the whole polhode, faint
  double line_scale = 1;            ///< momentum_sphere: its curves' widths and Π's dot; world: its arrows' thickness; times this
  bool tip_names = true;            ///< world: arrows named at their tips (false: the key names them)
  std::optional<std::array<bool, 3>> trail_axes;  ///< world: which axes' tips leave a trail here; none = [draw] trail_axes
  bool box = true;                  ///< world: the principal box's outline where [draw] box draws one (false: not in this view)
  std::optional<double> trail_seconds;  ///< world: s of axis-tip trail here; none = [draw] trails (a slow wobble needs a longer one)
  bool see_through = false;         ///< world: surfaces a little see-through, so an axis behind or inside them stays seen
  double L_width = 1;               ///< world: L's thickness times this (on top of line_scale): thinner than the axes it frames
  double omega_width = 1;           ///< world: ω's thickness times this (on top of line_scale): a spin axis along ω stays seen
  double trail_width = 1;           ///< world: the axis-tip trails' width times this (a small view's wobble reads bold)
  int levels = 10;                  ///< momentum_sphere: the family of other energies in this many steps
  bool key = true;                  ///< its key beside it (false: a neighbour's key says the same)
  std::optional<std::array<double, 2>> y_range;  ///< plot: the value axis; none = the whole run's range
  bool shade_speeds = true;         ///< plot: the slow-motion stretches shaded, one shade and key entry a speed
  bool y_log = false;               ///< plot: log10 of |value| (y_scale = "log"), for errors over decades
  /// plot of energy_error: dashed lines at L²/2I₁ and L²/2I₂ (and L²/2I₃), the energies a fixed |L| allows
  /// for a pure e₁ spin, the separatrix and a pure e₃ spin, as ΔE/E of the start's energy
  bool energy_levels = false;
  double appear = 0;                ///< simulated s from which the view is drawn (progressive reveal)
  std::string appear_text;          ///< as written ("flip 1 - 0.5")
  double until = 1e300;             ///< simulated s from which the view is no longer drawn (a closing segment's views replace it)
  /// world view of one body: its own readout lines under its title (time, state, angle, e2_angle of that body)
  std::optional<OverlayItems> readout;
  /// momentum_sphere `turn`: from the first frame showing simulated `at`, its
  /// fixed camera turns to `azimuth`/`elevation` over `seconds` of video (eased in and out).
  struct Turn {
    double at = 0, azimuth_deg = 0, elevation_deg = 0, seconds = 1;
  };
  std::optional<Turn> turn;
  /// momentum_sphere `build_up`: from the first frame showing simulated `at`,
  /// the figure drawn in four steps of `seconds` video s each: the |L| sphere,
  /// the energy ellipsoid, the curves where they meet, the separatrix (viz/sphere_reveal.hpp).
  struct BuildUp {
    double at = 0;
    std::array<double, 4> seconds{};
  };
  std::optional<BuildUp> build_up;
};

/// Names of the plot series, in the order of `plot_series_names()`.
const std::vector<std::string>& plot_series_names();
const char* view_kind_name(ViewKind k);

struct ExplainConfig {
  double time_scale = 1;           ///< [output] time_scale: simulated s per video s
  std::vector<SlowMotion> slow_motion;
  std::vector<Caption> captions;
  std::vector<Hold> holds;         ///< sorted by `at`
  TitleCard title;
  std::vector<ViewConfig> views;   ///< empty: the classic single world view (or [compare] grid)
  bool labels = false;             ///< [draw] labels: body names next to the bodies
  bool key = true;                 ///< [draw] key: each view's key of colours and meanings
  /// [draw] flips: the body whose flips are marked on screen ("flip 1", ...); none: no marks.
  std::optional<std::size_t> flip_marks;
  /// [draw] flip_badge: how long a flip's mark stays up, in video seconds in which the animation runs.
  double flip_badge_seconds = 2.0;
};

}  // namespace tumble::scene
