// The laid-out views of an explanatory video ([[views]]) and its text layers
// (captions, title card): turns the scene's settings and the simulated runs
// into GL-free draw-list views, one builder per view kind (src/viz).
#pragma once

#include <vector>

#include "compose/world_views.hpp"
#include "viz/key.hpp"
#include "viz/sphere_camera.hpp"

namespace tumble::compose {

class ExplainViews {
 public:
  ExplainViews(const WorldViews& world, const scene::Scene& s, const std::vector<scene::Run>& runs, int width, int height);
  /// One view per [[views]] table, each in its viewport.
  void add_views(viz::DrawList& dl, long k) const;
  /// Captions and the slow-motion badge over the whole frame.
  void add_text(viz::DrawList& dl, long k) const;
  /// Frame k as the title card (its own backdrop, no views), if it is one.
  bool title_card(viz::DrawList& dl, long k) const;

 private:
  struct Slot {
    int width_px = 0, height_px = 0;
    std::size_t body = 0;
    viz::Camera camera;         // world / body_frame (at t = 0)
    double lo = -1, hi = 1;     // plot: value range over the whole run
    viz::SphereCameraSettings sphere;     // momentum_sphere, poinsot
    std::vector<viz::SpherePose> track;   // momentum_sphere: the camera at each path sample
    std::optional<viz::KeySpot> key;      // its own key's place (none: merged into the frame key, or off)
  };
  /// View i at frame k; `layout`: for placing the keys (every frame's, before
  /// the first is drawn), so without them and with only what viz::keep_clear reads.
  viz::View view_at(std::size_t i, long k, bool layout = false) const;
  viz::View bodies_view(std::size_t i, long k, bool key) const;  // world, body_frame
  viz::View sphere_view(std::size_t i, long kk, bool layout) const;  // momentum_sphere at frame kk (< frames)
  viz::View plot_view(std::size_t i, long k) const;
  viz::View poinsot_view(std::size_t i, long kk, bool key) const;  // at frame kk (< frames)
  std::vector<viz::KeyEntry> key_entries(std::size_t i) const;
  void place_keys();
  std::vector<viz::Box> overlay_boxes() const;  // captions and badge over the whole video, frame px
  std::vector<viz::Box> frame_text_boxes(std::size_t i, long k) const;  // frame k's captions, badge, frame key: view i's px
  void place_frame_key(const std::vector<viz::Box>& taken);
  const WorldViews& world_;
  const scene::Scene& scene_;
  const std::vector<scene::Run>& runs_;
  int width_, height_;
  std::vector<Slot> slots_;
  std::vector<viz::KeyEntry> frame_key_;   // the entries of views too small for their own key
  glm::vec2 frame_key_at_{0};              // its top-left corner, frame px
  std::vector<std::string> notes_;         // the layout report's notes (why a key is not in its view)
};

/// Value of plot series `name` (scene::plot_series_names) for body `m` in state `s`; `e0` = energy at t = 0 (J).
double series_value(const std::string& name, const RigidBodyModel& m, const BodyState& s, double e0);

}  // namespace tumble::compose
