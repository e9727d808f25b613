// `tumble storyboard SCENE`: a PNG contact sheet of the scene's video (frames
// spread over it and one at every event), each tile labelled with its frame,
// video and simulated time, events and caption (run/storyboard.hpp).
#include <filesystem>
#include <iostream>
#include <memory>

#include "app/commands.hpp"
#include "app/progress.hpp"
#include "base/error.hpp"
#include "io/atomic_file.hpp"
#include "render/gl_context.hpp"
#include "run/storyboard.hpp"

namespace tumble::app {

namespace {

namespace fs = std::filesystem;

// Wider sheets than this are refused (GL's framebuffer limits; no viewer shows them whole).
constexpr int kMaxSheetWidth = 16384;

struct StoryboardOptions {
  std::string scene, out, gl, progress = "auto";
  FrameOverrides frame;
  int spread = 12, tile_width = 480, columns = 4;
  std::optional<int> gpu;
};

// The sheet's path, checked before any work by the files policy
// (io::check_output_file): a .png file name in a folder we can write (the
// default folder out/ is made), never an input of the run.
fs::path output_path(const StoryboardOptions& o, const scene::Scene& s) {
  fs::path out = o.out;
  if (out.empty()) {
    io::check_output_folder("-o", "out");
    out = fs::path("out") / (s.name + "_storyboard.png");
  }
  if (out.extension() != ".png")
    throw InputError("-o " + out.string() + ": expected a file name ending in .png (the sheet is a PNG)");
  io::check_output_file("-o", out);  // after the load: no spelling of the scene (or its meshes) passes
  return out;
}

int run_storyboard(const StoryboardOptions& o) {
  if (o.progress != "auto" && o.progress != "none")
    throw InputError("--progress: expected auto or none, found '" + o.progress + "'");
  const GlChoice gl = choose_gl(o.gl, o.gpu);
  scene::Scene s = load_scene_verbose(o.scene, frame_overrides(o.frame));
  scene::OutputConfig& out = s.render.output;
  out.apply_quality(scene::Quality::high, o.frame.msaa || !o.frame.aa.empty());  // render's default
  const auto [tile_w, tile_h] = run::tile_size(out.width, out.height, o.tile_width);
  (void)tile_h;
  if (o.columns * tile_w > kMaxSheetWidth)
    throw InputError("--columns " + std::to_string(o.columns) + " × tiles " + std::to_string(tile_w) +
                     " px wide would make the sheet wider than " + std::to_string(kMaxSheetWidth) +
                     " px; lower --columns or --tile-width");
  const fs::path path = output_path(o, s);
  ConsoleListener listener(o.progress != "none");
  const run::StoryboardSummary m = run::write_storyboard({s, path, o.spread, o.tile_width, o.columns, gl.backend, gl.gpu}, listener);
  std::cout << "storyboard of " << s.name << ": " << m.tiles.size() << (m.tiles.size() == 1 ? " tile" : " tiles")
            << " (frames";
  for (const compose::StoryTile& t : m.tiles) std::cout << " " << t.frame;
  std::cout << " of " << m.count << "), each " << m.tile_w << "x" << m.tile_h << ", sheet " << m.width << "x"
            << m.height << " written to " << path.string() << "\n";
  return m.diverged ? kDiverged : kOk;  // as render: the frames before the divergence are there
}

}  // namespace

void add_storyboard_command(CLI::App& app, Action& action) {
  const auto [cmd, o] = add_command(app, action, "storyboard",
                                    "One PNG contact sheet of a scene's video: frames spread over it and one at "
                                    "every event (flips, speed changes, holds, captions), each labelled",
                                    run_storyboard);
  cmd->add_option("-o,--out", o->out, "The sheet, a .png file (default out/<scene name>_storyboard.png)")->check(kPath);
  cmd->add_option("-n,--frames", o->spread, "Frames spread evenly over the video, first and last included, besides "
                                            "one at every event (default 12; 0: the events only)")
      ->check(CLI::Range(0, 200));
  cmd->add_option("--tile-width", o->tile_width,
                  "Tile width, px (default 480; the video's own width when narrower); frames are drawn at the "
                  "video's size and scaled down to it")
      ->check(CLI::Range(64, 3840));
  cmd->add_option("--columns", o->columns, "Tiles per row (default 4)")->check(CLI::Range(1, 16));
  add_frame_override_options(cmd, o->frame, false);
  cmd->add_option("--progress", o->progress, "auto (a bar on a terminal) or none");
  add_gl_options(cmd, o->gl, o->gpu);
}

}  // namespace tumble::app
