#include "compose/frame_builder.hpp"

#include "compose/views/kinds.hpp"
#include "compose/label_pins.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "scene/events.hpp"
#include "scene/frame_clock.hpp"
#include "viz/captions.hpp"
#include "viz/palette.hpp"
#include "viz/text_layout.hpp"

namespace tumble::compose {

namespace {

constexpr viz::Color kInk{0.12f, 0.13f, 0.16f, 1.0f};
constexpr viz::Color kDiverged{0.75f, 0.1f, 0.1f, 1.0f};
constexpr const char* kPaused = "paused";  // the badge while a [[holds]] stop lasts
constexpr double kCaptionSeam = 0.5;  // video s: a caption this close to the next cuts to it
constexpr const char* kWaiting = "paused: t = 0";  // a stop at t = 0, before anything has moved: says when it stands

int grid_columns(std::size_t runs) {
  const int n = std::max<int>(1, static_cast<int>(runs));
  return static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
}

// Whether a run gets a cell: every run, unless [compare] cells names some.
bool has_cell(const scene::Scene& s, const scene::Run& run) {
  const auto& cells = s.render.compare_cells;
  if (cells.empty()) return true;
  return std::any_of(cells.begin(), cells.end(), [&](Method m) { return method_name(m) == run.label; });
}

void move_text(viz::TextItem& t, glm::vec2 d) {
  t.position_px += d;
  if (t.backdrop.a > 0) t.backdrop_px += glm::vec4(d, d);
  if (t.subject_px.z > t.subject_px.x) t.subject_px += glm::vec4(d, d);
}

}  // namespace

FrameBuilder::~FrameBuilder() = default;

FrameBuilder::FrameBuilder(const scene::Scene& s, const std::vector<scene::Run>& runs, double fps, int width, int height)
    : scene_(s),
      runs_(runs),
      width_(width),
      height_(height),
      world_(s, runs, scene::frame_clock(s, fps), viz::text_px(viz::TextRole::label, height, s.render.draw.text_scale)),
      context_{s, runs, world_, height} {
  const auto& views = s.render.explain.views;
  // A [compare] grid's cells, in one row above the plots of its runs when it has any (or beside them).
  if (views.empty() || !s.render.compare_methods.empty()) {
    for (std::size_t r = 0; r < runs.size(); ++r) {
      if (!has_cell(s, runs[r])) continue;
      cell_runs_.push_back(r);
      panels_.push_back(make_run_panel(context_, r));
      titles_.push_back(runs.size() > 1 ? runs[r].title : "");
    }
    cells_ = panels_.size();
  }
  for (std::size_t i = 0; i < views.size(); ++i) {
    panels_.push_back(make_panel(context_, i));
    titles_.push_back(views[i].title);
  }
  FrameNeeds needs = frame_needs();
  mark_flips();
  // One caption strip; the scene reader makes every caption agree on where it goes.
  const auto& captions = s.render.explain.captions;
  if (!captions.empty() && captions.front().position == scene::CaptionPosition::top)
    needs.caption_side = FrameNeeds::CaptionSide::top;
  needs.badge = widest_status();
  plan_ = plan_frame(needs);
  give_back_key_strip(needs);
  // A [compare] grid's cells differ by a pixel or two (rounding, overlay
  // lines); fitted to one size, they share one camera and so one scale.
  glm::vec2 common{1e9f, 1e9f};
  for (std::size_t i = 0; i < cells_; ++i) {
    const viz::Box& c = plan_.views[i].content;
    common = glm::min(common, glm::vec2(c.x1 - c.x0, c.y1 - c.y0));
  }
  for (std::size_t i = 0; i < panels_.size(); ++i) {
    const viz::Box& c = plan_.views[i].content;
    const glm::vec2 size = i < cells_ ? common : glm::vec2(c.x1 - c.x0, c.y1 - c.y0);
    panels_[i]->fit(glm::max(size, glm::vec2(1.0f)));
  }
  // Names placed once for the whole run, clear of what the view shows in every frame.
  for (std::size_t i = 0; i < panels_.size(); ++i) {
    const viz::Box& c = plan_.views[i].content;
    pins_.push_back(pin_labels(*panels_[i], world_.clock(), {c.x1 - c.x0, c.y1 - c.y0},
                               viz::text_px(viz::TextRole::label, height_, scene_.render.draw.text_scale),
                               scene_.render.draw.tip_names_further));
  }
}

// What the layout needs: each panel's title, overlay lines, key and place.
FrameNeeds FrameBuilder::frame_needs() const {
  const auto& views = scene_.render.explain.views;
  FrameNeeds needs;
  needs.width = width_, needs.height = height_;
  needs.text_scale = scene_.render.draw.text_scale;
  needs.columns = views.empty() ? grid_columns(cells_) : std::max<int>(1, static_cast<int>(cells_));
  // One classic view: its legend is its key, beside the content (a wide frame has width to spare
  // and a spinning body needs height); a [compare] grid's, one key in rows above the captions.
  const bool single = cells_ == 1 && views.empty();
  if (cells_ > 0 && !single) needs.frame_key = legend();
  // Plots beside a [compare] grid: the cells share the band above the highest plot
  // (arrange = "row"), or the band left of the leftmost plot, in one row ("side").
  double band = 1, side = 1;
  if (cells_ > 0)
    for (const scene::ViewConfig& v : views) {
      band = std::min(band, v.viewport ? (*v.viewport)[1] : 1.0);
      side = std::min(side, v.viewport ? (*v.viewport)[0] : 1.0);
    }
  const bool stacked = scene_.render.compare_arrange == scene::CompareArrange::side && side > 0 && side < 1;
  for (std::size_t i = 0; i < panels_.size(); ++i) {
    ViewNeeds v;
    const scene::ViewConfig* vc = i < cells_ ? nullptr : &views[i - cells_];
    if (vc) v.viewport = vc->viewport;
    else if (stacked)
      v.viewport = std::array<double, 4>{side * double(i) / double(cells_), 0, side / double(cells_), 1};
    else if (!views.empty())
      v.viewport = std::array<double, 4>{double(i) / double(cells_), 0, 1.0 / double(cells_), band};
    v.kind = panels_[i]->name();
    v.title = titles_[i];
    v.large_overlay = i < cells_ && cells_ > 1;  // a comparison's readouts are what it compares
    v.overlay_lines = panels_[i]->overlay_lines();
    // A view may leave its key to a neighbour's; a grid's cells leave theirs to the frame key
    // (legend()), which says it once, so that a view with a key of its own keeps it beside it.
    if (vc ? vc->key : needs.frame_key.empty()) v.key = panels_[i]->key();
    v.edge_to_edge = vc && vc->kind == scene::ViewKind::plot;
    if (single) v.key = legend();
    needs.views.push_back(std::move(v));
  }
  for (const scene::Caption& c : scene_.render.explain.captions) needs.captions.push_back(c.text);
  return needs;
}

// The video times at which the marked body's flips are first shown. A mark
// stays up for [draw] flip_badge video seconds in which the animation runs (a
// hold does not use it up). Video time, not simulated: at ×1/8 the mark would
// otherwise stay up long after the flip, at ×4 flash by.
void FrameBuilder::mark_flips() {
  if (!scene_.render.explain.flip_marks) return;
  const scene::FrameClock& clock = world_.clock();
  long k = 0;
  for (double flip : scene::body_flip_times(scene_, *scene_.render.explain.flip_marks)) {
    flip_t_.push_back(flip);
    while (k < clock.count() && clock.time(k) < flip - 1e-9) ++k;
    if (k >= clock.count()) break;
    long end = k;
    const long up = std::lround(scene_.render.explain.flip_badge_seconds * clock.fps());
    for (long running = 0; end < clock.count() && running < up; ++end)
      if (!clock.in_hold(end)) ++running;
    flip_frames_.emplace_back(k, end);
  }
}

// The badge of frame k: a flip's mark ("flip 2") for a while after it, and the
// speed while the video does not run in real time ("×1/8 slow motion", "paused").
std::string FrameBuilder::status(long k) const {
  const scene::FrameClock& clock = world_.clock();
  const double rate = clock.rate(k);
  std::string out;
  // In a comparison the flips marked are the exact solution's, not a method's: say so.
  const std::string flip = scene_.render.compare_methods.empty() ? "flip " : "exact flip ";
  for (std::size_t i = 0; i < flip_frames_.size(); ++i)
    if (k >= flip_frames_[i].first && k < flip_frames_[i].second) out = flip + std::to_string(i + 1);
  const std::string speed = clock.in_hold(k) ? (clock.time(k) == 0 ? kWaiting : kPaused)
                            : rate == 1      ? ""
                                             : scene::speed_text(rate) + (rate < 1 ? " slow motion" : " fast");
  // Held at a flip, the whole hold: a deliberate stop, named ("paused at flip 1").
  for (std::size_t i = 0; i < flip_t_.size(); ++i)
    if (clock.in_hold(k) && std::abs(clock.time(k) - flip_t_[i]) < 1e-6) return std::string(kPaused) + " at " + flip + std::to_string(i + 1);
  // A stop the scene gives a reason: the reason, so the hall knows what to look at.
  for (const scene::Hold& h : scene_.render.explain.holds)
    if (clock.in_hold(k) && !h.label.empty() && std::abs(clock.time(k) - h.at) < 1e-6) return std::string(kPaused) + ": " + h.label;
  if (!speed.empty()) out += (out.empty() ? "" : "  \u00b7  ") + speed;
  return out;
}

// The widest badge the video shows ("" when it has none).
std::string FrameBuilder::widest_status() const {
  std::string widest;
  const float size = viz::text_px(viz::TextRole::badge, height_, scene_.render.draw.text_scale);
  for (long k = 0; k < world_.clock().count(); ++k) {
    const std::string t = status(k);
    if (viz::text_width(t, size) > viz::text_width(widest, size)) widest = t;
  }
  return widest;
}

// A classic scene's legend: one key for the frame, what its arrows and box mean.
std::vector<viz::KeyEntry> FrameBuilder::legend() const {
  if (!scene_.render.draw.legend) return {};
  std::vector<viz::KeyEntry> key = bodies_key(context_, std::nullopt, true);
  if (const auto box = box_key(context_)) key.push_back(*box);
  // A comparison's cells but the exact one carry the exact body faintly (WorldViews::view).
  const auto exact = std::find_if(runs_.begin(), runs_.end(), [](const scene::Run& r) { return r.label == "exact"; });
  const bool ghosts = runs_.size() > 1 && exact != runs_.end() &&
                      std::any_of(cell_runs_.begin(), cell_runs_.end(), [&](std::size_t r) { return runs_[r].label != "exact"; });
  if (ghosts) key.push_back({viz::Swatch::block, {kGhostColor}, "grey body: the exact solution"});
  return key;
}

viz::View FrameBuilder::view_at(std::size_t i, long k, std::vector<std::string>& notes) const {
  const ViewPlan& p = plan_.views[i];
  viz::View v = panels_[i]->content(k);
  const viz::Box& c = p.content;
  // Pinned names go to their places for the run, with their leaders; then
  // arrows are named at their tips and labels settle inside the content
  // rectangle, clear of the view's other text and of the leaders (named
  // "leader" meanwhile, as obstacles; drawn unnamed, as annotations); then all
  // move with it into the view.
  std::vector<viz::TextItem> pinned;
  for (viz::TextItem& t : v.texts)
    if (const auto pin = pins_[i].find(t.name); pin != pins_[i].end()) t.position_px = pin->second, pinned.push_back(t);
  const std::size_t first_leader = v.polylines.size();
  add_leaders(v, pinned, {c.x1 - c.x0, c.y1 - c.y0});
  for (std::size_t j = first_leader; j < v.polylines.size(); ++j) v.polylines[j].name = "leader";
  viz::label_arrow_tips(v, c.x1 - c.x0, c.y1 - c.y0, viz::text_px(viz::TextRole::label, height_, scene_.render.draw.text_scale),
                        scene_.render.draw.tip_names_further);
  pinned.clear();
  std::vector<viz::Box> pinned_boxes;
  for (auto t = v.texts.begin(); t != v.texts.end();) {
    const auto pin = pins_[i].find(t->name);
    if (pin == pins_[i].end()) {
      ++t;
      continue;
    }
    t->position_px = pin->second;
    pinned_boxes.push_back(viz::text_box(*t));
    pinned.push_back(std::move(*t));
    t = v.texts.erase(t);
  }
  for (const viz::TextItem& t : viz::settle_labels(v, c.x1 - c.x0, c.y1 - c.y0, pinned_boxes))
    notes.push_back(view_name(i, panels_[i]->name(), titles_[i]) + ": label '" + t.text + "' left out: no place beside it clear of " +
                    "the view's other text, bodies, arrows and curves");
  for (std::size_t j = first_leader; j < v.polylines.size(); ++j)
    if (v.polylines[j].name == "leader") v.polylines[j].name.clear();
  v.texts.insert(v.texts.end(), pinned.begin(), pinned.end());
  for (viz::TextItem& t : v.texts) move_text(t, {c.x0, c.y0});
  v.content_px = glm::vec4(c.x0, c.y0, c.x1, c.y1);
  v.viewport = p.viewport;
  // A comparison's cells name their methods, and give their readouts, in the method's colour (as its plot curve).
  const bool method = i < cells_ && cells_ > 1;
  const viz::Color ink = method ? run_color(runs_[cell_runs_[i]]) : kInk;
  const viz::Color title_ink = method ? ink : viz::color_of(viz::Meaning::ink, 0.95f);
  if (!p.title.empty()) v.texts.push_back({p.title, p.title_at, p.title_px, title_ink, "view_title"});
  const std::vector<std::string> lines = panels_[i]->overlay(k);
  for (std::size_t j = 0; j < lines.size(); ++j) {
    const bool diverged = lines[j].rfind("diverged", 0) == 0;
    v.texts.push_back({lines[j], {p.title_at.x > 0 ? p.title_at.x : c.x0, p.overlay_y + static_cast<float>(j) * p.overlay_px},
                       p.overlay_px, diverged ? kDiverged : ink, diverged ? "diverged" : "overlay"});
  }
  if (p.key_at) viz::add_key(v, p.key, *p.key_at, p.key_px);
  return v;
}

std::vector<std::pair<std::size_t, float>> FrameBuilder::captions_at(long k) const {
  const scene::FrameClock& clock = world_.clock();
  const double tau = static_cast<double>(k) / clock.fps();  // video time
  std::vector<std::pair<std::size_t, float>> out;
  const auto& captions = scene_.render.explain.captions;
  std::vector<std::pair<double, double>> spans;
  for (const scene::Caption& c : captions) spans.push_back(scene::caption_video_span(clock, c));
  for (std::size_t i = 0; i < captions.size(); ++i) {
    // Up from the first frame showing `start` to the last showing `end` (through a hold there); a caption
    // up to the run's end does not fade out, so the video's last frame still says what it shows.
    auto [start, last] = spans[i];
    const bool to_end = captions[i].seconds <= 0 && captions[i].end >= scene_.simulation.duration;
    // One caption followed by the next within half a second cuts to it: a fade out and a fade in
    // between them would leave the frame without words for most of a second.
    bool cut_in = false, cut_out = false;
    for (std::size_t j = 0; j < spans.size(); ++j) {
      if (j == i) continue;
      if (spans[j].first > last && spans[j].first - last < kCaptionSeam) {
        cut_out = true;
        last = spans[j].first - 0.5 / clock.fps();
      }
      if (start > spans[j].second && start - spans[j].second < kCaptionSeam) cut_in = true;
    }
    if (tau < start || tau > last) continue;
    const double end = to_end || cut_out ? last + 1e6 : last;
    const float a = viz::fade_alpha(tau, cut_in ? start - 1e6 : start, end);
    if (a > 0) out.emplace_back(i, a);
  }
  return out;
}

void FrameBuilder::add_frame_text(viz::DrawList& dl, long k) const {
  const glm::vec2 shift{0, plan_.caption_shift};
  for (const auto& [i, a] : captions_at(k)) {
    for (viz::TextItem& t : viz::caption_items(scene_.render.explain.captions[i].text, a, width_, height_, plan_.badge_side)) {
      move_text(t, shift);
      dl.texts.push_back(std::move(t));
    }
  }
  if (const auto badge = viz::speed_badge(status(k), false, width_, height_, true, scene_.render.draw.text_scale)) {
    viz::TextItem b = *badge;
    b.position_px.y = plan_.badge_y;
    // In a comparison red is a method's colour (Euler's): the badge is ink there, not a method's words.
    if (!scene_.render.compare_methods.empty()) b.color = viz::color_of(viz::Meaning::ink);
    move_text(b, shift);
    dl.texts.push_back(std::move(b));
  }
  const std::vector<viz::KeyEntry> key = frame_key_at(world_.clock().time(k));
  if (!key.empty()) {
    const viz::Box& b = plan_.frame_key_box;
    viz::add_key_row(dl.texts, key, 0.5f * (b.x0 + b.x1), b.y0 + 0.5f * plan_.frame_key_px, plan_.frame_key_px,
                     b.x1 - b.x0 - plan_.frame_key_px);
  }
}

// The frame key's entries at simulated t: the frame's own legend, and those of views shown
// then (a view that appears later, or has gone, adds nothing its frame does not draw).
std::vector<viz::KeyEntry> FrameBuilder::frame_key_at(double t) const {
  std::vector<viz::KeyEntry> out;
  for (std::size_t e = 0; e < plan_.frame_key.size(); ++e) {
    const auto& from = e < plan_.frame_key_from.size() ? plan_.frame_key_from[e] : std::vector<std::size_t>{};
    if (from.empty() ? plan_.frame_key_always : std::any_of(from.begin(), from.end(), [&](std::size_t i) { return shown(i, t); }))
      out.push_back(plan_.frame_key[e]);
  }
  return out;
}

bool FrameBuilder::title_card(viz::DrawList& dl, long k) const {
  const scene::TitleCard& t = scene_.render.explain.title;
  if (t.hold <= 0 || !world_.clock().on_title_card(k)) return false;
  const double tau = static_cast<double>(k) / world_.clock().fps();
  dl.background = viz::kTitleCardBackground;
  dl.views.clear();
  for (viz::TextItem& item : viz::title_items(t.text, t.subtitle, viz::fade_alpha(tau, -1.0, t.hold), width_, height_))
    dl.texts.push_back(std::move(item));
  return true;
}

// The frame key's strip is drawn only while a view it speaks for is on screen:
// a view whose span never meets theirs (a closing segment's) is laid out as
// if the frame had no frame key, and so takes the strip's height too.
void FrameBuilder::give_back_key_strip(FrameNeeds needs) {
  if (plan_.frame_key.empty() || plan_.frame_key_always || plan_.frame_key_in_corner) return;
  const auto span = [&](std::size_t i) {
    if (i < cells_) return std::pair<double, double>{-1e300, 1e300};
    const scene::ViewConfig& v = scene_.render.explain.views[i - cells_];
    return std::pair<double, double>{v.appear, v.until};
  };
  const auto meets_keyed = [&](std::size_t i) {
    return std::any_of(plan_.frame_key_views.begin(), plan_.frame_key_views.end(), [&](std::size_t j) {
      return span(i).first < span(j).second && span(j).first < span(i).second;
    });
  };
  for (std::size_t j : plan_.frame_key_views) needs.views[j].key.clear();
  const FramePlan free = plan_frame(needs);
  if (!free.frame_key.empty()) return;
  for (std::size_t i = 0; i < panels_.size(); ++i)
    if (!meets_keyed(i)) plan_.views[i] = free.views[i];
}

// Whether panel i is drawn at simulated t: a [compare] cell always, a view
// from its `appear` until its `until` (a later segment's views take its room).
bool FrameBuilder::shown(std::size_t i, double t) const {
  if (i < cells_) return true;
  const scene::ViewConfig& v = scene_.render.explain.views[i - cells_];
  return t >= v.appear && t < v.until;
}

viz::DrawList FrameBuilder::build(long k) const {
  viz::DrawList dl;
  const Eigen::Vector3d& bg = scene_.render.output.background;
  dl.background = {static_cast<float>(bg.x()), static_cast<float>(bg.y()), static_cast<float>(bg.z()), 1.0f};
  if (title_card(dl, k)) return dl;  // the animation waits
  dl.notes = plan_.notes;
  const double t = world_.clock().time(k);
  for (std::size_t i = 0; i < panels_.size(); ++i)
    if (shown(i, t)) dl.views.push_back(view_at(i, k, dl.notes));  // revealed in order, in their room
  add_frame_text(dl, k);
  return dl;
}

}  // namespace tumble::compose
