// `tumble storyboard SCENE`: one PNG contact sheet of a scene's video, some
// frames spread over it and one at every event (compose/storyboard.hpp), each
// drawn by the frame pipeline at the video's size (the pixels `tumble render`
// writes), scaled to the tile and labelled under it with its frame number,
// video and simulated time, events and caption.
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "compose/storyboard.hpp"
#include "render/gl_context.hpp"
#include "run/listener.hpp"
#include "scene/scene.hpp"

namespace tumble::run {

struct StoryboardRequest {
  const scene::Scene& scene;      ///< its [output] holds the command's options (size, fps, aa)
  std::filesystem::path out;      ///< the PNG, written atomically
  int spread = 12;                ///< frames spread evenly over the video (besides the events)
  int tile_width = 480;           ///< px; the video's own width when it is narrower
  int columns = 4;
  render::GlBackend backend = render::GlBackend::osmesa;
  std::optional<int> gpu = {};
};

struct StoryboardSummary {
  std::vector<compose::StoryTile> tiles;
  long count = 0;                 ///< frames of the video
  int tile_w = 0, tile_h = 0, width = 0, height = 0;
  bool diverged = false;          ///< the simulation stopped early: the sheet shows the frames before
};

/// The tile size for a `frame_w` × `frame_h` video at `tile_width`: as wide,
/// or the video's own size when it is narrower, the video's aspect kept.
std::pair<int, int> tile_size(int frame_w, int frame_h, int tile_width);

/// Simulates, draws and writes the storyboard of `r`. Throws InputError (no
/// frame to show) or io::IoError; layout notes and auto's picks go to `l`.
StoryboardSummary write_storyboard(const StoryboardRequest& r, Listener& l);

}  // namespace tumble::run
