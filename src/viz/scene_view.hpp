// Builds the GL-free draw list of one view from a snapshot of body states.
#pragma once

#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "core/body.hpp"
#include "core/particle_cloud.hpp"
#include "viz/body_look.hpp"
#include "viz/draw_list.hpp"
#include "viz/draw_options.hpp"
#include "viz/palette.hpp"

namespace tumble::viz {

/// One body at one instant, with what is needed to draw it.
struct BodySnapshot {
  const RigidBodyModel* model = nullptr;
  const ParticleCloud* cloud = nullptr;  ///< optional: particles in cloud coordinates
  BodyState state;
  Color color{0.55f, 0.62f, 0.78f, 0.35f};  ///< box face colour (alpha = translucency)
  const BodyLook* look = nullptr;        ///< optional: surfaces, visible particles and their colours
  std::string label;                     ///< what a label shows (the display name); empty: the model's name
};

// From the one colour table (viz/palette.hpp).
inline const Color kAxisColors[3] = {color_of(Meaning::axis1), color_of(Meaning::axis2), color_of(Meaning::axis3)};
inline const Color kLColor = color_of(Meaning::L);
inline const Color kOmegaColor = color_of(Meaning::omega);

/// Axis arrows reach past the box face by this factor, so their heads stay visible.
inline constexpr double kAxisOvershoot = 1.3;
/// ... and reach at least this many largest half extents: a flat body's
/// normal (a T-handle's e₃) stays long enough to read when seen at a slant.
inline constexpr double kAxisLeast = 0.6;
/// L's line runs from kLBehind to kLReach body sizes (largest half extents)
/// either side of the centre, ω's arrow kOmegaReach: both past the axes.
inline constexpr double kLBehind = 0.5, kLReach = 1.6, kOmegaReach = 1.35;

/// World position of the tip of principal axis `i` (0..2) of a body: the axis
/// runs from the centre of mass through the box face (at least kAxisLeast of the
/// largest half extent, so a flat body still shows all three axes).
glm::dvec3 axis_tip(const RigidBodyModel& m, const BodyState& s, int i);

/// Per-body history of axis-tip positions, for trails. Fed every sample from
/// t = 0 (frames and sub-frame samples), so a frame range renders the same
/// trails as a full run.
class TrailRecorder {
 public:
  void record(double t, const std::vector<BodySnapshot>& bodies);
  /// Polylines of the last `seconds` before and including `t`; `only`: of that body alone.
  std::vector<PolylineItem> polylines(double t, double seconds, std::array<bool, 3> axes = {true, true, true},
                                      std::optional<std::size_t> only = std::nullopt) const;

 private:
  struct Sample {
    double t;
    std::vector<std::array<glm::dvec3, 3>> tips;  // per body
  };
  std::deque<Sample> samples_;
};

/// The box drawn for body `b`: its principal-axis box around its surfaces
/// (an outline: no faces), else around its particles when they are drawn.
BoxItem body_box(const BodySnapshot& b, const DrawOptions& opt);

/// Adds the items of `bodies` to `view` (camera and label are the caller's).
void add_bodies(View& view, const std::vector<BodySnapshot>& bodies, const DrawOptions& opt,
                const TrailRecorder* trails, double t);

/// Adds a faint copy of each body's surfaces, every part in `tint` (its alpha
/// too), named "ghost" and drawn `behind`: where a reference solution has the body, so a
/// departure from it shows.
void add_ghosts(View& view, const std::vector<BodySnapshot>& bodies, Color tint);

/// Radius of a body's particle spheres, m: a fixed fraction of its size.
double particle_radius(const RigidBodyModel& m);

/// A bounding sphere (centre, radius in m) of a body's box.
double box_radius(const RigidBodyModel& m);

/// Camera that frames all the points in `centres` with their radii, looking
/// from a fixed 3/4 direction; `aspect` = width/height of the viewport.
Camera auto_camera(const std::vector<glm::dvec3>& centres, const std::vector<double>& radii, double fov_y_deg,
                   double aspect);

}  // namespace tumble::viz
