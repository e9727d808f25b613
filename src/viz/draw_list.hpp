// GL-free description of one frame: what to draw, in world coordinates.
// The simulation side (viz) fills it from a snapshot of body states; the
// render layer turns it into GL draw calls. Nothing here includes GL, so the
// contents can be unit-tested without a context (MuJoCo's mjvScene idea).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "viz/camera_up.hpp"

namespace tumble::viz {

/// Linear RGBA colour, components in [0, 1].
using Color = glm::vec4;

/// An oriented box: the body's extents along its principal axes.
struct BoxItem {
  glm::dvec3 center;        ///< world position of the box centre, m
  glm::dmat3 rotation;      ///< columns = box axes in world (right-handed)
  glm::dvec3 half_extents;  ///< half sizes along the columns of `rotation`, m
  Color face;               ///< lit translucent face colour (alpha < 1)
  Color edge;               ///< crisp edge line colour
};

/// The eight world corners of `b` (what the layout report and the keys' placement call the body).
inline std::vector<glm::dvec3> box_corners(const BoxItem& b) {
  std::vector<glm::dvec3> out;
  for (int i = 0; i < 8; ++i)
    out.push_back(b.center + b.rotation * (b.half_extents * glm::dvec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1)));
  return out;
}

/// An arrow from `origin` to `origin + vector` (world, m).
struct ArrowItem {
  glm::dvec3 origin;
  glm::dvec3 vector;
  double radius;            ///< shaft radius, m (head scales with it)
  Color color;
  std::string name = {};    ///< in the layout report (empty: not reported)
  std::string tip = {};     ///< its name drawn at its tip ("e₁", "L"; viz::label_arrow_tips), empty: none
  int tip_rank = 0;         ///< lower ranks are named first and keep their place
};

/// A particle drawn as a small sphere/point sprite.
struct PointItem {
  glm::dvec3 position;      ///< world, m
  double radius;            ///< m
  Color color;              ///< drawn opaque (a lit ball): its alpha is not used, so fade a point by its rgb
  std::string name = {};    ///< in the layout report, e.g. "momentum_point" (empty: not reported)
};

/// A mesh as flat-shaded triangles, 3 vertices each, in its own (cloud) axes, m.
struct SurfaceMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;   ///< unit, outward
};

/// A lit, opaque mesh surface placed by `model` (its axes -> world, m). Shared,
/// so a frame's list does not copy the triangles and the renderer can keep them on the GPU.
struct SurfaceItem {
  std::shared_ptr<const SurfaceMesh> mesh;
  glm::dmat4 model;
  Color color;
  std::string name = {};    ///< e.g. "ellipsoid": a key keeps clear of a named surface
  /// Drawn a little further away in depth than it lies: where it coincides
  /// with an opaque surface (a reference ghost on a body that keeps to it),
  /// that surface shows whole instead of in stripes of both (z-fighting).
  bool behind = false;
  /// A body's part drawn see-through (a world view's see_through): still solid
  /// for the arrows' names, which keep off it as off an opaque part.
  bool see_through = false;
};

/// One level of detail of a body's particles, in its cloud axes.
struct ParticleLevel {
  std::vector<glm::vec3> positions;   ///< cloud axes, m
  std::vector<Color> colors;
  /// Per particle, the grid directions it is seen through (viz/particle_set.hpp), never 0.
  std::vector<std::uint8_t> exposed;
  float radius = 0;                   ///< m, sphere radius of every particle of this level
};

/// A body's visible particles at several levels of detail, finest first. Made
/// once per body and shared by every frame, so the renderer keeps it on the GPU.
struct ParticleSet {
  std::vector<ParticleLevel> levels;
  glm::vec3 center{0};      ///< cloud axes, m: centre of a sphere bounding the particles
  float bound_radius = 0;   ///< m
};

/// A body's particles placed by `model` (cloud axes -> world, rigid). The
/// renderer picks the level (viz::particle_level) and skips the particles
/// facing away from the eye (viz::faces_eye).
struct ParticlesItem {
  std::shared_ptr<const ParticleSet> set;
  glm::dmat4 model;
};

/// A polyline (trail of an axis tip); alpha fades from oldest to newest.
struct PolylineItem {
  std::vector<glm::dvec3> points;  ///< world, m, oldest first
  Color color;
  float width_px;
  bool fade = true;                ///< false: one alpha along the line (curves, plots)
  std::string name = {};           ///< in the layout report (empty: not reported)
  /// Drawn after the translucent surfaces, over them: a curve on the near side
  /// of a glassy surface (a polhode on the inertia ellipsoid) in full colour.
  bool over_glass = false;
};

/// Ground grid in the plane through `origin` with normal +z (world).
struct GridItem {
  glm::dvec3 origin;
  double spacing;           ///< m between lines
  int half_count;           ///< lines on each side of the origin
  Color color;
};

/// Screen-space text, pixel coordinates from the viewport's top-left corner.
/// '\n' breaks lines; each line is `size_px` high (viz/text_layout.hpp).
struct TextItem {
  std::string text;
  glm::vec2 position_px;    ///< top-left corner of the first line
  float size_px;
  Color color;
  std::string name = {};    ///< in the layout report ("text" when empty)
  /// Filled rectangle drawn just before the text (alpha 0: none), over
  /// `backdrop_px` = x0, y0, x1, y1 in the viewport's pixels.
  Color backdrop{0, 0, 0, 0};
  glm::vec4 backdrop_px{0};
  bool key = false;         ///< part of a key (the layout report's kind "key")
  /// What a label names (a body's box on screen), x0, y0, x1, y1 in the
  /// viewport's pixels; x1 <= x0: none. viz::settle_labels keeps the label beside it.
  glm::vec4 subject_px{0};
  /// A named polyline this label names: once the label is pinned (compose/label_pins),
  /// a thin leader in its colour runs from the label to the curve's nearest point.
  std::string leader_to = {};
};

/// Perspective camera (GLM lookAt/perspective conventions).
struct Camera {
  glm::dvec3 position{4.0, -6.0, 3.0};  ///< m
  glm::dvec3 target{0.0, 0.0, 0.0};     ///< m
  glm::dvec3 up{0.0, 0.0, 1.0};
  double fov_y_deg = 35.0;              ///< vertical field of view, degrees
  double near_m = 0.05, far_m = 500.0;
  /// > 0: orthographic, showing ± this many m vertically (plots); 0 = perspective.
  double ortho_half_height = 0;
};

/// The camera's up, or the fallback of viz/camera_up.hpp when it is parallel
/// to the view direction (a camera that follows a body can come to look along it).
/// An Eigen vector as GLM's: the physics is in Eigen, draw lists in GLM.
inline glm::dvec3 to_glm(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

inline glm::dvec3 view_up(const Camera& c) {
  const glm::dvec3 d = c.target - c.position;
  const Eigen::Vector3d u = usable_up({c.up.x, c.up.y, c.up.z}, {d.x, d.y, d.z});
  return {u.x(), u.y(), u.z()};
}

/// One viewport's content. Several of them form a comparison grid.
struct View {
  Camera camera;
  std::vector<BoxItem> boxes;
  std::vector<ArrowItem> arrows;
  std::vector<PointItem> points;
  std::vector<ParticlesItem> particles;
  std::vector<SurfaceItem> surfaces;
  std::vector<PolylineItem> polylines;
  std::vector<GridItem> grids;
  std::vector<TextItem> texts;   ///< overlay, drawn last, in this viewport
  std::string name;              ///< in the layout report, e.g. "momentum_sphere" (empty: its index)
  /// x, y, width, height as fractions of the frame from its top-left corner;
  /// unset = the view's cell of the DrawList's grid.
  std::optional<glm::dvec4> viewport;
  /// The content rectangle, x0, y0, x1, y1 in the view's pixels: the camera
  /// sees through it and every 3D item is clipped (scissored) to it, so no
  /// arrow reaches the view's title or key strips; unset = the whole view.
  /// Texts stay in the view's pixels.
  std::optional<glm::vec4> content_px;
  /// A sphere figure's ball on screen (centre x, y and radius, view px): names
  /// settle beside it, never onto its face, where a name reads as a point there.
  std::optional<glm::vec3> ball_px;
};

/// A whole frame: views laid out on a grid of `columns` (row-major).
struct DrawList {
  Color background{0.97f, 0.97f, 0.98f, 1.0f};
  int columns = 1;
  std::vector<View> views;
  std::vector<TextItem> texts;   ///< overlay over the whole frame
  /// For the layout report only (kind "note"): e.g. why a view has no key of its own.
  std::vector<std::string> notes;
};

}  // namespace tumble::viz
