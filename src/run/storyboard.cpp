#include "run/storyboard.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "base/error.hpp"
#include "compose/frame_builder.hpp"
#include "compose/layout_notes.hpp"
#include "io/image_ops.hpp"
#include "io/png.hpp"
#include "render/renderer.hpp"
#include "scene/frame_clock.hpp"

namespace tumble::run {

namespace {

std::string seconds(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f s", s);
  return b;
}

// What the label under frame k's tile says.
compose::TileText tile_text(const scene::Scene& s, const scene::FrameClock& clock, const compose::FrameBuilder& b,
                            const compose::StoryTile& tile) {
  const long k = tile.frame;
  compose::TileText t;
  char t_sim[48];
  std::snprintf(t_sim, sizeof t_sim, "t = %.3f s", clock.time(k));
  t.head = "frame " + std::to_string(k) + "   video " + seconds(static_cast<double>(k) / clock.fps()) + "   " + t_sim;
  const double rate = clock.rate(k);
  if (clock.on_title_card(k)) t.head += "   title card";
  else if (rate == 0) t.head += "   paused";
  else if (rate != 1) t.head += "   " + scene::speed_text(rate);
  for (const std::string& e : tile.events) t.events += (t.events.empty() ? "" : " \u00b7 ") + e;
  for (const auto& [i, alpha] : b.captions_at(k))
    t.caption += (t.caption.empty() ? "" : " / ") + ("\u201c" + s.render.explain.captions[i].text + "\u201d");
  return t;
}

std::string sheet_title(const scene::Scene& s, const StoryboardSummary& m, double fps, long last) {
  const scene::OutputConfig& out = s.render.output;
  char b[300];
  std::snprintf(b, sizeof b, "%s: %zu frames of 0-%ld (video %.2f s at %g fps), drawn at %dx%d, shown at %dx%d",
                s.name.c_str(), m.tiles.size(), m.count - 1, static_cast<double>(m.count - 1) / fps, fps, out.width,
                out.height, m.tile_w, m.tile_h);
  std::string title = b;
  if (last < m.count - 1) title += "; the simulation stopped after frame " + std::to_string(last);
  return title;
}

// Every tile's frame drawn at the video's size, scaled to the tile and pasted in.
void draw_tiles(const StoryboardRequest& r, render::GlContext& ctx, const compose::FrameBuilder& builder,
                const compose::SheetPlan& plan, const std::vector<compose::StoryTile>& tiles, io::Image& sheet,
                Listener& l) {
  const scene::OutputConfig& out = r.scene.render.output;
  render::Renderer renderer(ctx, out.width, out.height, out.aa, out.msaa);
  compose::LayoutNotes notes;
  l.begin(static_cast<long>(tiles.size()), "drawing " + std::to_string(tiles.size()) + " frames");
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const viz::DrawList dl = builder.build(tiles[i].frame);
    notes.add(tiles[i].frame, dl.notes);
    const glm::ivec2 at = plan.tile_at(i);
    io::paste(sheet, io::resized(renderer.render(dl), plan.tile_w, plan.tile_h), at.x, at.y);
    l.advance(static_cast<long>(i + 1));
  }
  l.end();
  warn_layout(notes, l);
}

}  // namespace

std::pair<int, int> tile_size(int frame_w, int frame_h, int tile_width) {
  const int w = std::min(frame_w, tile_width);
  return {w, std::max(1, static_cast<int>(std::lround(static_cast<double>(w) * frame_h / frame_w)))};
}

StoryboardSummary write_storyboard(const StoryboardRequest& r, Listener& l) {
  const scene::Scene& s = r.scene;
  const scene::OutputConfig& out = s.render.output;
  const scene::FrameClock clock = scene::frame_clock(s, out.fps);
  StoryboardSummary m;
  m.count = clock.count();
  const std::vector<scene::Run> runs = scene::simulate_runs(s, m.count, out.fps);
  for (const scene::Run& run : runs)
    for (const std::string& note : run.auto_notes) l.note(note);
  // A single run stops at its divergence: the sheet shows the frames before.
  const long last = (runs.size() == 1 ? static_cast<long>(runs[0].frames.size()) : m.count) - 1;
  if (last < 0) throw InputError(s.name + ": no frame to show: " + runs[0].diverged.value_or("the run stopped"));
  m.diverged = last < m.count - 1;
  if (m.diverged) l.note(runs[0].diverged.value_or("the simulation stopped early") + "; the storyboard shows frames 0-" + std::to_string(last));
  const compose::FrameBuilder builder(s, runs, out.fps, out.width, out.height);
  m.tiles = compose::story_tiles(compose::story_events(s, clock, last), r.spread, last);
  std::tie(m.tile_w, m.tile_h) = tile_size(out.width, out.height, r.tile_width);
  std::vector<compose::TileText> texts;
  for (const compose::StoryTile& t : m.tiles) texts.push_back(tile_text(s, clock, builder, t));
  const std::string title = sheet_title(s, m, out.fps, last);
  const compose::SheetPlan plan = compose::plan_sheet(title, texts, r.columns, m.tile_w, m.tile_h);
  m.width = plan.width, m.height = plan.height;
  std::unique_ptr<render::GlContext> ctx;
  try {
    ctx = render::create_gl_context(r.backend, r.gpu);
  } catch (const std::invalid_argument& e) {  // --gpu / TUMBLE_EGL_DEVICE past the last device
    throw InputError(e.what());
  }
  io::Image sheet = io::filled(plan.width, plan.height, 247, 247, 250);
  draw_tiles(r, *ctx, builder, plan, m.tiles, sheet, l);
  {  // the labels, then the header: text drawn by the same renderer as the frames' text
    render::Renderer labels(*ctx, plan.tile_w, plan.label_h, scene::Antialias::none);
    for (std::size_t i = 0; i < texts.size(); ++i) {
      const glm::ivec2 at = plan.tile_at(i);
      io::paste(sheet, labels.render(compose::tile_label(plan, texts[i])), at.x, at.y + plan.tile_h);
    }
  }
  render::Renderer header(*ctx, plan.width, plan.header_h, scene::Antialias::none);
  io::paste(sheet, header.render(compose::sheet_header(plan, title)), 0, 0);
  io::write_png_atomic(r.out, sheet);
  return m;
}

}  // namespace tumble::run
