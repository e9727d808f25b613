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
  std::string kind;   ///< "text", "marker", "arrow", "curve", "key", "body" (a box's corners) or "note" (why a key is not drawn)
  viz::Box box;       ///< frame px, top-left origin
  bool visible = true;  ///< false: outside its view, behind an opaque sphere, under a backdrop or key, or transparent
  std::string text;   ///< text and key items: their text
  float size_px = 0;  ///< text and key items: line height
};

/// Every text (named or not), every body's box ("body") and every named point
/// ("marker"), arrow and polyline ("curve") of `dl` in a frame_w × frame_h
/// frame, then the draw list's notes ("note", no box, not visible).
std::vector<LayoutItem> layout_items(const viz::DrawList& dl, int frame_w, int frame_h);

/// One JSON Lines record per item: frame, view, name, kind, box, visible (and text, size_px).
void write_layout(std::ostream& out, long frame, const std::vector<LayoutItem>& items);

}  // namespace tumble::compose
