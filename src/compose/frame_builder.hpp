// Everything drawn in frame k of a scene, as a GL-free viz::DrawList: the
// classic view (or [compare] grid) of bodies in space, or the scene's
// [[views]], each a Panel in its place of the frame's layout (FramePlan), with
// its title, overlay and key in their strips, the captions in theirs, and the
// title card. What MuJoCo's mjv is to mjr: src/render draws the list, tests
// inspect it without GL.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "compose/frame_layout.hpp"
#include "compose/panel.hpp"
#include "compose/world_views.hpp"
#include "scene/frame_clock.hpp"
#include "scene/frame_runs.hpp"
#include "scene/scene.hpp"
#include "viz/draw_list.hpp"

namespace tumble::compose {

class FrameBuilder {
 public:
  /// Keeps references to `s` and `runs` (scene::simulate_runs at `fps`).
  FrameBuilder(const scene::Scene& s, const std::vector<scene::Run>& runs, double fps, int width, int height);
  ~FrameBuilder();
  viz::DrawList build(long k) const;

  const scene::FrameClock& clock() const { return world_.clock(); }
  float font_px() const { return world_.font_px(); }
  /// The frame's layout (decided once, for every frame; a view that is never on
  /// screen with the frame key's views is laid out without its strip).
  const FramePlan& plan() const { return plan_; }
  /// The captions frame k shows (index into the scene's captions) and their opacity, > 0.
  std::vector<std::pair<std::size_t, float>> captions_at(long k) const;

 private:
  bool shown(std::size_t i, double t) const;
  std::vector<viz::KeyEntry> frame_key_at(double t) const;
  viz::View view_at(std::size_t i, long k, std::vector<std::string>& notes) const;
  void add_frame_text(viz::DrawList& dl, long k) const;
  bool title_card(viz::DrawList& dl, long k) const;
  std::vector<viz::KeyEntry> legend() const;
  FrameNeeds frame_needs() const;
  void give_back_key_strip(FrameNeeds needs);
  void mark_flips();
  std::string status(long k) const;
  std::string widest_status() const;

  const scene::Scene& scene_;
  const std::vector<scene::Run>& runs_;
  int width_, height_;
  WorldViews world_;
  PanelContext context_;
  std::vector<std::unique_ptr<Panel>> panels_;
  std::vector<std::string> titles_;
  std::size_t cells_ = 0;  // panels of runs first (a classic view or a [compare] grid), then the [[views]]
  std::vector<std::size_t> cell_runs_;  // the run each cell draws ([compare] cells may leave runs to the plots)
  FramePlan plan_;
  std::vector<std::pair<long, long>> flip_frames_;  // each marked flip's badge: its first frame, one past its last
  std::vector<double> flip_t_;      // simulated s of each marked flip
  std::vector<std::map<std::string, glm::vec2>> pins_;  // per panel: its names placed once for the run (label_pins.hpp)
};

}  // namespace tumble::compose
