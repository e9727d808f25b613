#include "compose/frame_builder.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "scene/frame_clock.hpp"
#include "viz/captions.hpp"
#include "viz/palette.hpp"
#include "viz/text_layout.hpp"

namespace tumble::compose {

namespace {

constexpr viz::Color kInk{0.12f, 0.13f, 0.16f, 1.0f};
constexpr viz::Color kDiverged{0.75f, 0.1f, 0.1f, 1.0f};
constexpr const char* kPaused = "paused";  // the badge while a [[holds]] stop lasts

int grid_columns(std::size_t runs) {
  const int n = std::max<int>(1, static_cast<int>(runs));
  return static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
}

// The widest speed badge the video shows ("" when it runs in real time throughout).
std::string widest_speed(const scene::FrameClock& clock, int frame_h) {
  std::string widest;
  const float size = viz::text_px(viz::TextRole::caption, frame_h);
  double last = 1;
  for (long k = 0; k < clock.count(); ++k) {
    const double rate = clock.rate(k);
    if (rate == last || rate == 1) continue;
    last = rate;
    const std::string t = clock.in_hold(k) ? kPaused : scene::speed_text(rate);
    if (viz::text_width(t, size) > viz::text_width(widest, size)) widest = t;
  }
  return widest;
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
      world_(s, runs, scene::frame_clock(s, fps), viz::text_px(viz::TextRole::label, height)),
      context_{s, runs, world_, height} {
  const auto& views = s.render.explain.views;
  FrameNeeds needs;
  needs.width = width, needs.height = height;
  if (views.empty()) {
    needs.columns = grid_columns(runs.size());
    for (std::size_t r = 0; r < runs.size(); ++r) {
      panels_.push_back(make_run_panel(context_, r));
      titles_.push_back(runs.size() > 1 ? runs[r].label : "");
    }
    needs.legend = legend();
  } else {
    for (std::size_t i = 0; i < views.size(); ++i) {
      panels_.push_back(make_panel(context_, i));
      titles_.push_back(views[i].title);
    }
  }
  for (std::size_t i = 0; i < panels_.size(); ++i) {
    ViewNeeds v;
    if (!views.empty()) v.viewport = views[i].viewport;
    v.kind = panels_[i]->name();
    v.title = titles_[i];
    v.overlay_lines = panels_[i]->overlay_lines();
    if (views.empty() || views[i].key) v.key = panels_[i]->key();  // a view may leave its key to a neighbour's
    v.edge_to_edge = !views.empty() && views[i].kind == scene::ViewKind::plot;
    needs.views.push_back(std::move(v));
  }
  for (const scene::Caption& c : s.render.explain.captions) needs.captions.push_back(c.text);
  // One caption strip; the scene reader makes every caption agree on where it goes.
  const auto& captions = s.render.explain.captions;
  if (!captions.empty() && captions.front().position == scene::CaptionPosition::top)
    needs.caption_side = FrameNeeds::CaptionSide::top;
  needs.badge = widest_speed(world_.clock(), height);
  plan_ = plan_frame(needs);
  for (std::size_t i = 0; i < panels_.size(); ++i) {
    const viz::Box& c = plan_.views[i].content;
    panels_[i]->fit({std::max(1.0f, c.x1 - c.x0), std::max(1.0f, c.y1 - c.y0)});
  }
}

std::string FrameBuilder::legend() const {
  const viz::DrawOptions& draw = world_.draw();
  if (!scene_.render.draw.legend || !draw.axes) return "";
  std::string legend = "principal axes:  red = smallest moment   green = intermediate   blue = largest";
  if (draw.angular_momentum) legend += "   orange = L";
  if (draw.omega) legend += "   purple = omega";
  return legend;
}

viz::View FrameBuilder::view_at(std::size_t i, long k, std::vector<std::string>& notes) const {
  const ViewPlan& p = plan_.views[i];
  viz::View v = panels_[i]->content(k);
  const viz::Box& c = p.content;
  // Labels settle inside the content rectangle, clear of its other text; then move with it into the view.
  for (const viz::TextItem& t : viz::settle_labels(v, c.x1 - c.x0, c.y1 - c.y0))
    notes.push_back(view_name(i, panels_[i]->name(), titles_[i]) + ": label '" + t.text + "' left out: no place beside it clear of " +
                    "the view's other text, bodies, arrows and curves");
  for (viz::TextItem& t : v.texts) move_text(t, {c.x0, c.y0});
  v.content_px = glm::vec4(c.x0, c.y0, c.x1, c.y1);
  v.viewport = p.viewport;
  if (!p.title.empty()) v.texts.push_back({p.title, p.title_at, p.title_px, viz::color_of(viz::Meaning::ink, 0.95f), "view_title"});
  const std::vector<std::string> lines = panels_[i]->overlay(k);
  for (std::size_t j = 0; j < lines.size(); ++j) {
    const bool diverged = lines[j].rfind("diverged", 0) == 0;
    v.texts.push_back({lines[j], {p.title_at.x > 0 ? p.title_at.x : c.x0, p.overlay_y + static_cast<float>(j) * p.overlay_px},
                       p.overlay_px, diverged ? kDiverged : kInk, diverged ? "diverged" : "overlay"});
  }
  if (p.key_at) viz::add_key(v, p.key, *p.key_at, p.key_px);
  return v;
}

std::vector<std::pair<std::size_t, float>> FrameBuilder::captions_at(long k) const {
  const scene::FrameClock& clock = world_.clock();
  const double tau = static_cast<double>(k) / clock.fps();  // video time
  std::vector<std::pair<std::size_t, float>> out;
  const auto& captions = scene_.render.explain.captions;
  for (std::size_t i = 0; i < captions.size(); ++i) {
    // Up from the first frame showing `start` to the last showing `end` (through a hold there).
    const float a = viz::fade_alpha(tau, clock.video_time(captions[i].start), clock.video_time_last(captions[i].end));
    if (a > 0) out.emplace_back(i, a);
  }
  return out;
}

void FrameBuilder::add_frame_text(viz::DrawList& dl, long k) const {
  const scene::FrameClock& clock = world_.clock();
  const double rate = clock.rate(k);
  const glm::vec2 shift{0, plan_.caption_shift};
  for (const auto& [i, a] : captions_at(k)) {
    for (viz::TextItem& t : viz::caption_items(scene_.render.explain.captions[i].text, a, width_, height_, plan_.badge_side)) {
      move_text(t, shift);
      dl.texts.push_back(std::move(t));
    }
  }
  const auto badge = clock.in_hold(k) ? viz::speed_badge(kPaused, false, width_, height_, true)
                                      : viz::speed_badge(scene::speed_text(rate), rate < 1, width_, height_);
  if (badge) {
    viz::TextItem b = *badge;
    move_text(b, shift);
    dl.texts.push_back(std::move(b));
  }
  if (!plan_.frame_key.empty()) {
    const viz::Box& b = plan_.frame_key_box;
    viz::add_key_row(dl.texts, plan_.frame_key, 0.5f * static_cast<float>(width_), b.y0 + 0.5f * plan_.frame_key_px,
                     plan_.frame_key_px, static_cast<float>(width_) - plan_.frame_key_px);
  }
  if (plan_.legend.y1 > plan_.legend.y0) {
    const float pad = 0.5f * plan_.legend_px;
    dl.texts.push_back({viz::wrap_text(legend(), plan_.legend_px, static_cast<float>(width_) - 2 * pad),
                        {pad, plan_.legend.y0 + pad}, plan_.legend_px, kInk, "legend"});
  }
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

viz::DrawList FrameBuilder::build(long k) const {
  viz::DrawList dl;
  const Eigen::Vector3d& bg = scene_.render.output.background;
  dl.background = {static_cast<float>(bg.x()), static_cast<float>(bg.y()), static_cast<float>(bg.z()), 1.0f};
  if (title_card(dl, k)) return dl;  // the animation waits
  dl.notes = plan_.notes;
  const double t = world_.clock().time(k);
  const auto& views = scene_.render.explain.views;
  for (std::size_t i = 0; i < panels_.size(); ++i)
    if (views.empty() || t >= views[i].appear) dl.views.push_back(view_at(i, k, dl.notes));  // revealed in order, in their room
  add_frame_text(dl, k);
  return dl;
}

}  // namespace tumble::compose
