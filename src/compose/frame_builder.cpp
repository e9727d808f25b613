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
    const std::string t = scene::speed_text(rate);
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
    v.title = titles_[i];
    v.overlay_lines = panels_[i]->overlay_lines();
    v.key = panels_[i]->key();
    v.edge_to_edge = !views.empty() && views[i].kind == scene::ViewKind::plot;
    needs.views.push_back(std::move(v));
  }
  for (const scene::Caption& c : s.render.explain.captions) needs.captions.push_back(c.text);
  needs.badge = widest_speed(world_.clock(), height);
  plan_ = plan_frame(needs);
  for (std::size_t i = 0; i < panels_.size(); ++i) {
    const viz::Box& c = plan_.views[i].content;
    panels_[i]->fit({std::max(1.0f, c.x1 - c.x0), std::max(1.0f, c.y1 - c.y0)});
  }
  keys_.reserve(needs.views.size());
  for (ViewNeeds& v : needs.views) keys_.push_back(std::move(v.key));
}

std::string FrameBuilder::legend() const {
  const viz::DrawOptions& draw = world_.draw();
  if (!scene_.render.draw.legend || !draw.axes) return "";
  std::string legend = "principal axes:  red = smallest moment   green = intermediate   blue = largest";
  if (draw.angular_momentum) legend += "   orange = L";
  if (draw.omega) legend += "   purple = omega";
  return legend;
}

viz::View FrameBuilder::view_at(std::size_t i, long k) const {
  const ViewPlan& p = plan_.views[i];
  viz::View v = panels_[i]->content(k);
  const viz::Box& c = p.content;
  // Labels settle inside the content rectangle, clear of its other text; then move with it into the view.
  viz::settle_labels(v, c.x1 - c.x0, c.y1 - c.y0);
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
  if (p.key_at) viz::add_key(v, keys_[i], *p.key_at, p.key_px);
  return v;
}

void FrameBuilder::add_frame_text(viz::DrawList& dl, long k) const {
  const scene::FrameClock& clock = world_.clock();
  const double tau = static_cast<double>(k) / clock.fps();  // video time
  const double rate = clock.rate(k);
  const glm::vec2 shift{0, plan_.caption_shift};
  for (const scene::Caption& c : scene_.render.explain.captions) {
    const float a = viz::fade_alpha(tau, clock.video_time(c.start), clock.video_time(c.end));
    if (a <= 0) continue;
    for (viz::TextItem& t : viz::caption_items(c.text, a, width_, height_, plan_.badge_side)) {
      move_text(t, shift);
      dl.texts.push_back(std::move(t));
    }
  }
  if (auto badge = viz::speed_badge(scene::speed_text(rate), rate < 1, width_, height_)) {
    move_text(*badge, shift);
    dl.texts.push_back(std::move(*badge));
  }
  if (plan_.legend.y1 > plan_.legend.y0) {
    const float pad = 0.5f * plan_.legend_px;
    dl.texts.push_back({viz::wrap_text(legend(), plan_.legend_px, static_cast<float>(width_) - 2 * pad),
                        {pad, plan_.legend.y0 + pad}, plan_.legend_px, kInk, "legend"});
  }
  dl.notes = plan_.notes;
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
  for (std::size_t i = 0; i < panels_.size(); ++i) dl.views.push_back(view_at(i, k));
  add_frame_text(dl, k);
  return dl;
}

}  // namespace tumble::compose
