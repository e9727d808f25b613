// A storyboard (contact sheet) of a scene's video, GL-free: which frames it
// shows (some spread over the video, and one at every event: the title card,
// each change of speed, each body's flips, each caption), where each tile and
// its label go on the sheet, and the labels' text as draw lists. src/run draws
// the tiles with the frame pipeline and pastes them in.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/frame_clock.hpp"
#include "scene/scene.hpp"
#include "viz/draw_list.hpp"

namespace tumble::compose {

/// A frame worth a tile, and why ("flip 1", "×1/8 slow motion", "caption 2").
struct StoryMoment {
  long frame = 0;
  std::string why;
};

/// The events of `s`'s video at `clock`, in frames up to `last`: the title
/// card, each stretch of another speed (slow motion, a hold) where it starts,
/// each body's flips (the first frame showing the flip or later) and each
/// caption (the first frame showing it fully). In frame order.
std::vector<StoryMoment> story_events(const scene::Scene& s, const scene::FrameClock& clock, long last);

/// One tile: its frame and the events it shows.
struct StoryTile {
  long frame = 0;
  std::vector<std::string> events;
};

/// `spread` frames spread evenly over 0..last (both ends among them), and the
/// frame of every event: in frame order, each frame once with all its events.
std::vector<StoryTile> story_tiles(const std::vector<StoryMoment>& events, int spread, long last);

/// What the label under a tile says: its first line (frame, video and
/// simulated time, speed), the events, and the caption showing ("": none).
struct TileText {
  std::string head, events, caption;
};

/// The sheet: a header line, then tiles in rows of `columns`, each with its
/// label strip (as tall as the tallest label) under it.
struct SheetPlan {
  int columns = 1, tile_w = 0, tile_h = 0;
  int gap = 0, header_h = 0, label_h = 0;
  float text_px = 0;        ///< the labels' text size
  int width = 0, height = 0;
  std::size_t tiles = 0;
  /// The top-left corner of tile i, sheet px (its label starts tile_h below it).
  glm::ivec2 tile_at(std::size_t i) const;
};

/// The sheet headed by `title` for `labels` (one per tile) of tile_w × tile_h tiles in rows of `columns`.
SheetPlan plan_sheet(const std::string& title, const std::vector<TileText>& labels, int columns, int tile_w, int tile_h);

/// The label strip of one tile (tile_w × label_h px): head, events, caption wrapped to the tile.
viz::DrawList tile_label(const SheetPlan& plan, const TileText& text);

/// The header strip (width × header_h px): `title`, wrapped to the sheet.
viz::DrawList sheet_header(const SheetPlan& plan, const std::string& title);

}  // namespace tumble::compose
