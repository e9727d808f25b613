// A view kind as one object: a Panel answers what the frame layout asks (its
// key, the lines its title strip holds besides the title) and draws its
// content at frame k in the content rectangle the layout gave it. One file per
// kind under compose/views/, one row per kind in kViewKinds (view_kinds.cpp).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "compose/world_views.hpp"
#include "scene/frame_runs.hpp"
#include "scene/scene.hpp"
#include "viz/draw_list.hpp"
#include "viz/key.hpp"

namespace tumble::compose {

/// What every panel draws from.
struct PanelContext {
  const scene::Scene& scene;
  const std::vector<scene::Run>& runs;
  const WorldViews& world;
  int frame_h;  ///< the frame's height, px (text sizes)
  /// Text sizes' scale ([draw] text_scale): viz::text_px(role, frame_h, text_scale()).
  double text_scale() const { return scene.render.draw.text_scale; }
};

class Panel {
 public:
  virtual ~Panel() = default;
  /// The view's name in the layout report, e.g. "momentum_sphere".
  virtual std::string name() const = 0;
  /// Its key's entries (none: no key strip).
  virtual std::vector<viz::KeyEntry> key() const { return {}; }
  /// Lines of text under its title (the overlay line), at most `overlay_lines()` of them, frame k.
  virtual std::vector<std::string> overlay(long) const { return {}; }
  virtual int overlay_lines() const { return 0; }
  /// Called once, when the layout has given it a content rectangle of `size_px`
  /// (cameras are fitted to it here, over the whole video).
  virtual void fit(glm::vec2 size_px) = 0;
  /// Frame k's content: its camera, the 3D items and the labels of what they
  /// show, text in content px (0, 0 = the content rectangle's top-left).
  virtual viz::View content(long k) const = 0;
};

/// The panel of `[[views]]` table `index` (its kind's row of kViewKinds).
std::unique_ptr<Panel> make_panel(const PanelContext& ctx, std::size_t index);

/// The panel of run `r`'s world view in a scene without [[views]] (one per cell of a [compare] grid).
std::unique_ptr<Panel> make_run_panel(const PanelContext& ctx, std::size_t r);

/// Frame k of `run`, or its last when it stopped earlier (-1: it has none).
long last_frame(const scene::Run& run, long k);

}  // namespace tumble::compose
