// `tumble render --layout FILE`: where every reported item of a frame lands,
// computed GL-free from the draw list and the cameras' projections (the same
// view_layout.hpp and text sizes the renderer draws with), so tests can see
// what a viewer sees without pixels. One JSON object per item per frame.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "viz/draw_list.hpp"
#include "viz/text_layout.hpp"

namespace tumble::compose {

struct LayoutItem {
  std::string view;   ///< "frame" (overlay) or "<index>:<view name>"
  std::string name;   ///< e.g. "momentum_point", "caption", "key"
  std::string kind;   ///< "text", "marker", "arrow", "curve", "key", "body" (a box's corners), "surface" (a body's
                      ///< drawn triangles), "content" (a view's
                      ///< content rectangle) or "note" (what the layout left out, and why)
  viz::Box box;       ///< frame px, top-left origin; an arrow's whole extent (shaft and head), a curve's every point
  bool visible = true;  ///< false: outside its content rectangle, behind an opaque sphere, under a backdrop or key, or transparent
  std::string text;   ///< text and key items: their text
  float size_px = 0;  ///< text and key items: line height
  /// Arrows: tail and tip; curves: every point (frame px, in front of the camera), for overlap tests.
  std::vector<glm::vec2> path;
};

/// Each view's content rectangle ("content"), every text (named or not), every
/// body's box ("body") and every named point ("marker"), arrow and polyline
/// ("curve") of `dl` in a frame_w × frame_h frame, then the draw list's notes
/// ("note", no box, not visible).
std::vector<LayoutItem> layout_items(const viz::DrawList& dl, int frame_w, int frame_h);

/// One JSON Lines record per item: frame, view, name, kind, box, visible (and text,
/// size_px; an arrow's tail "from" and tip "to").
void write_layout(std::ostream& out, long frame, const std::vector<LayoutItem>& items);

}  // namespace tumble::compose
