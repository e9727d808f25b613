#include "compose/storyboard.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.hpp"
#include "scene/events.hpp"
#include "viz/palette.hpp"
#include "viz/text_layout.hpp"

namespace tumble::compose {

namespace {

constexpr viz::Color kSheetBackground{0.97f, 0.97f, 0.98f, 1.0f};
constexpr viz::Color kEventInk{0.70f, 0.12f, 0.10f, 1.0f};  // the speed badge's red
constexpr viz::Color kCaptionInk{0.25f, 0.27f, 0.32f, 1.0f};
constexpr float kLine = 1.25f;  // line pitch of the labels, in sizes
constexpr float kTitleSize = 1.2f;  // the sheet's title, in label sizes

// The first frame at or after video time `tau` (s).
long frame_from(double tau, double fps) { return static_cast<long>(std::ceil(tau * fps - 1e-6)); }

// What a stretch of the clock is called where it starts.
std::string speed_event(const scene::ClockSpan& span, bool after_title) {
  if (span.rate == 0) return "hold";
  const std::string speed = span.rate == 1 ? "real time" : scene::speed_text(span.rate) + (span.rate < 1 ? " slow motion" : " fast");
  return after_title ? "animation starts, " + speed : speed;
}

void add_flips(const scene::Scene& s, const scene::FrameClock& clock, std::vector<StoryMoment>& out) {
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    std::vector<double> flips;
    try {
      flips = scene::body_flip_times(s, b);
    } catch (const Diverged&) {  // its run diverges too: the sheet shows what came before, without flips
      continue;
    }
    for (std::size_t i = 0; i < flips.size(); ++i)
      out.push_back({frame_from(clock.video_time(flips[i]), clock.fps()),
                     "flip " + std::to_string(i + 1) + (s.bodies.size() > 1 ? " of " + s.bodies[b].name : "")});
  }
}

void add_captions(const scene::Scene& s, const scene::FrameClock& clock, std::vector<StoryMoment>& out) {
  const auto& captions = s.render.explain.captions;
  for (std::size_t i = 0; i < captions.size(); ++i) {
    const auto [v0, v1] = scene::caption_video_span(clock, captions[i]);
    // viz::fade_alpha's fade in: 0.4 s, at most a quarter of the caption's time.
    out.push_back({frame_from(v0 + std::min(0.4, 0.25 * (v1 - v0)), clock.fps()), "caption " + std::to_string(i + 1)});
  }
}

std::string wrapped(const std::string& text, float px, float width) { return viz::wrap_text(text, px, width); }

int lines_of(const TileText& t, float px, float width) {
  int n = 1;
  if (!t.events.empty()) n += viz::text_lines(wrapped(t.events, px, width));
  if (!t.caption.empty()) n += viz::text_lines(wrapped(t.caption, px, width));
  return n;
}

}  // namespace

std::vector<StoryMoment> story_events(const scene::Scene& s, const scene::FrameClock& clock, long last) {
  std::vector<StoryMoment> out;
  if (clock.hold() > 0) out.push_back({0, "title card"});
  const std::vector<scene::ClockSpan> spans = scene::clock_spans(clock);
  for (std::size_t i = 1; i < spans.size(); ++i)
    out.push_back({spans[i].first, speed_event(spans[i], clock.on_title_card(spans[i - 1].first))});
  add_flips(s, clock, out);
  add_captions(s, clock, out);
  std::erase_if(out, [&](const StoryMoment& m) { return m.frame < 0 || m.frame > last; });
  std::stable_sort(out.begin(), out.end(), [](const StoryMoment& a, const StoryMoment& b) { return a.frame < b.frame; });
  return out;
}

std::vector<StoryTile> story_tiles(const std::vector<StoryMoment>& events, int spread, long last) {
  std::map<long, std::vector<std::string>> frames;
  for (int i = 0; i < spread; ++i)
    frames[spread == 1 ? 0 : std::lround(static_cast<double>(i) * static_cast<double>(last) / (spread - 1))];
  for (const StoryMoment& m : events) frames[m.frame].push_back(m.why);
  std::vector<StoryTile> out;
  for (auto& [k, why] : frames) out.push_back({k, std::move(why)});
  return out;
}

glm::ivec2 SheetPlan::tile_at(std::size_t i) const {
  const int c = static_cast<int>(i % static_cast<std::size_t>(columns)), r = static_cast<int>(i / static_cast<std::size_t>(columns));
  return {gap + c * (tile_w + gap), header_h + r * (tile_h + label_h + gap)};
}

SheetPlan plan_sheet(const std::string& title, const std::vector<TileText>& labels, int columns, int tile_w,
                     int tile_h) {
  SheetPlan p;
  p.tiles = labels.size();
  p.columns = std::max(1, std::min(columns, static_cast<int>(std::max<std::size_t>(1, labels.size()))));
  p.tile_w = tile_w, p.tile_h = tile_h;
  // Readable under a tile of any width: 2.6 % of a 640 px tile, never under 12 px.
  p.text_px = std::clamp(static_cast<float>(tile_w) / 38.0f, 12.0f, 24.0f);
  p.gap = static_cast<int>(std::lround(p.text_px));
  int lines = 1;
  for (const TileText& t : labels) lines = std::max(lines, lines_of(t, p.text_px, static_cast<float>(tile_w)));
  p.label_h = static_cast<int>(std::ceil((static_cast<float>(lines) * kLine + 0.5f) * p.text_px));
  const int rows = static_cast<int>((labels.size() + static_cast<std::size_t>(p.columns) - 1) / static_cast<std::size_t>(p.columns));
  p.width = p.columns * tile_w + (p.columns + 1) * p.gap;
  const float title_px = kTitleSize * p.text_px;
  const int title_lines = viz::text_lines(wrapped(title, title_px, static_cast<float>(p.width - 2 * p.gap)));
  p.header_h = static_cast<int>(std::ceil((static_cast<float>(title_lines) + 1.2f) * title_px));
  p.height = p.header_h + rows * (tile_h + p.label_h + p.gap);
  return p;
}

viz::DrawList tile_label(const SheetPlan& plan, const TileText& text) {
  viz::DrawList dl;
  dl.background = kSheetBackground;
  const float px = plan.text_px, w = static_cast<float>(plan.tile_w);
  float y = 0.3f * px;
  auto add = [&](const std::string& s, viz::Color color, const char* name) {
    if (s.empty()) return;
    const std::string lines = wrapped(s, px, w);
    dl.texts.push_back({lines, {0, y}, px, color, name});
    y += static_cast<float>(viz::text_lines(lines)) * kLine * px;
  };
  add(text.head, viz::color_of(viz::Meaning::ink), "tile_head");
  add(text.events, kEventInk, "tile_events");
  add(text.caption, kCaptionInk, "tile_caption");
  return dl;
}

viz::DrawList sheet_header(const SheetPlan& plan, const std::string& title) {
  viz::DrawList dl;
  dl.background = kSheetBackground;
  const float px = kTitleSize * plan.text_px;
  dl.texts.push_back({wrapped(title, px, static_cast<float>(plan.width - 2 * plan.gap)),
                      {static_cast<float>(plan.gap), 0.6f * px}, px, viz::color_of(viz::Meaning::ink), "sheet_title"});
  return dl;
}

}  // namespace tumble::compose
