// Arrows named at their tips ("e₁", "L", "ω"), as a textbook figure labels its
// vectors, so that colour is never the only key. GL-free, from the view's
// draw list: each name goes just past its arrow's head along the arrow as
// drawn, turned a little at a time until it is clear of the other arrows, the
// named curves, the bodies' parts, the view's text and the names placed before it.
#include <algorithm>
#include <cmath>
#include <optional>

#include "viz/captions.hpp"
#include "viz/text_layout.hpp"

namespace tumble::viz {

namespace {

struct Segment {
  glm::vec2 a, b;
  float r;  // half its drawn width, px, and a little room
};

bool segment_hits(const Segment& s, const Box& box) {
  constexpr int kSteps = 24;
  for (int i = 0; i <= kSteps; ++i) {
    const glm::vec2 p = s.a + (s.b - s.a) * (static_cast<float>(i) / kSteps);
    if (p.x + s.r > box.x0 && p.x - s.r < box.x1 && p.y + s.r > box.y0 && p.y - s.r < box.y1) return true;
  }
  return false;
}

// The screen length of a world length `r` at `p` (0 behind the camera).
float screen_len(const ViewportProjection& project, const Camera& cam, const glm::dvec3& p, double r) {
  glm::vec2 a, b;
  if (!project(p, a) || !project(p + r * glm::normalize(view_up(cam)), b)) return 0.0f;
  return glm::length(b - a);
}

// Each surface part's box on screen: the parts of a T-handle are its two bars.
std::vector<Box> part_boxes(const View& view, const ViewportProjection& project) {
  std::vector<Box> out;
  for (const SurfaceItem& s : view.surfaces) {
    // A body's parts (unnamed, opaque or see-through); a translucent veil or a figure's plane ("plane") takes no name off.
    if (!s.mesh || (s.color.a < 1.0f && !s.see_through) || !s.name.empty()) continue;
    Box b{1e30f, 1e30f, -1e30f, -1e30f};
    for (const glm::vec3& v : s.mesh->positions) {
      glm::vec2 px;
      if (!project(glm::dvec3(s.model * glm::dvec4(glm::dvec3(v), 1.0)), px)) continue;
      b = {std::min(b.x0, px.x), std::min(b.y0, px.y), std::max(b.x1, px.x), std::max(b.y1, px.y)};
    }
    if (b.x0 < b.x1) out.push_back(b);
  }
  return out;
}

// What a tip's name is tried in turn: along the arrow, then turned either way.
constexpr float kTurns[] = {0.0f, 0.5f, -0.5f, 1.0f, -1.0f, 1.5f, -1.5f, 2.0f, -2.0f, 2.6f, -2.6f};

// What a name must keep clear of: arrow shafts and named curves, arrow heads,
// and boxes already taken (the bodies' parts, the view's text, earlier names).
struct Obstacles {
  std::vector<Segment> shafts;
  std::vector<glm::vec2> heads;  // tip centre
  std::vector<float> head_r;     // its radius, px
  std::vector<Box> taken;

  bool clear(const Box& b) const {
    if (std::any_of(taken.begin(), taken.end(), [&](const Box& o) { return o.overlaps(b); })) return false;
    if (std::any_of(shafts.begin(), shafts.end(), [&](const Segment& s) { return segment_hits(s, b); })) return false;
    for (std::size_t h = 0; h < heads.size(); ++h)
      if (heads[h].x + head_r[h] > b.x0 && heads[h].x - head_r[h] < b.x1 && heads[h].y + head_r[h] > b.y0 &&
          heads[h].y - head_r[h] < b.y1)
        return false;
    return true;
  }
};

Obstacles obstacles_of(const View& view, const ViewportProjection& project, float leader_room) {
  Obstacles o;
  for (const ArrowItem& a : view.arrows) {
    glm::vec2 p0, p1;
    if (!project(a.origin, p0) || !project(a.origin + a.vector, p1)) continue;
    const float r = screen_len(project, view.camera, a.origin + a.vector, 2.4 * a.radius);
    o.shafts.push_back({p0, p1, std::max(2.0f, screen_len(project, view.camera, a.origin, a.radius)) + 1.5f});
    o.heads.push_back(p1);
    o.head_r.push_back(r + 1.5f);
  }
  // The curves a viewer follows (named: a polhode, a herpolhode), as short
  // segments; a curve name's leader with `leader_room` (px) either side.
  for (const PolylineItem& l : view.polylines) {
    if (l.name.empty()) continue;
    const float r = l.name == "leader" ? std::max(2.0f, leader_room) : 2.0f;
    glm::vec2 a, b;
    for (std::size_t i = 1; i < l.points.size(); ++i)
      if (project(l.points[i - 1], a) && project(l.points[i], b)) o.shafts.push_back({a, b, r});
  }
  // The named dots (a Poinsot contact point, larger than ω's head at its place) as drawn.
  for (const PointItem& p : view.points) {
    glm::vec2 c;
    if (p.name.empty() || !project(p.position, c)) continue;
    o.heads.push_back(c);
    o.head_r.push_back(screen_len(project, view.camera, p.position, p.radius) + 1.5f);
  }
  o.taken = part_boxes(view, project);
  for (const TextItem& t : view.texts) o.taken.push_back(text_box(t));
  return o;
}

// The first place, turning from along the arrow, where `a`'s name (its tip
// projected at `base` → `tip`) fits the view clear of `o`; nullopt if none.
std::optional<TextItem> place_tip(const ArrowItem& a, glm::vec2 base, glm::vec2 tip, float head, const Obstacles& o,
                                  glm::vec2 view_px, float label_px, int reaches) {
  const InkSpan ink = text_ink(a.tip, label_px);
  const glm::vec2 along = tip - base;
  const float len = glm::length(along);
  const glm::vec2 d0 = len > 0.3f * label_px ? along / len : glm::vec2(0, -1);
  // Just past the head; where every turn is taken (a tip inside the body, L along an axis), a line or two further out.
  for (int r = 0; r < reaches; ++r)
  for (const float turn : kTurns) {
    const float further = static_cast<float>(r);
    const glm::vec2 d{d0.x * std::cos(turn) - d0.y * std::sin(turn), d0.x * std::sin(turn) + d0.y * std::cos(turn)};
    const float reach = head + 0.5f * (std::abs(d.x) * ink.width() + std::abs(d.y) * label_px) + (0.2f + further) * label_px;
    const glm::vec2 centre = tip + reach * d;
    TextItem t{a.tip, {centred_x(a.tip, label_px, centre.x), centre.y - 0.5f * label_px}, label_px, a.color,
               "tip:" + (a.name.empty() ? a.tip : a.name)};
    t.color.a = 1.0f;
    const Box b = text_box(t);
    if (b.x0 < 0 || b.y0 < 0 || b.x1 > view_px.x || b.y1 > view_px.y) continue;
    if (o.clear(b)) return t;
  }
  return std::nullopt;
}

}  // namespace

std::vector<std::string> label_arrow_tips(View& view, float width_px, float height_px, float label_px, bool further) {
  const ViewportProjection project(view.camera, width_px, height_px);
  // A name just beside a curve name's leader reads as the one it leads to:
  // each name looks first for a place a third of a line from every leader,
  // then for any place clear of them.
  Obstacles roomy = obstacles_of(view, project, 0.35f * label_px), o = obstacles_of(view, project, 0.0f);
  // L first, then ω, then the axes: the quantities the lesson is about keep their place.
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < view.arrows.size(); ++i)
    if (!view.arrows[i].tip.empty()) order.push_back(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return view.arrows[a].tip_rank < view.arrows[b].tip_rank; });
  std::vector<std::string> left_out;
  for (std::size_t i : order) {
    const ArrowItem& a = view.arrows[i];
    glm::vec2 base, tip;
    if (!project(a.origin, base) || !project(a.origin + a.vector, tip)) continue;
    const float head = screen_len(project, view.camera, a.origin + a.vector, 2.4 * a.radius);
    std::optional<TextItem> t = place_tip(a, base, tip, head, roomy, {width_px, height_px}, label_px, further ? 3 : 1);
    if (!t) t = place_tip(a, base, tip, head, o, {width_px, height_px}, label_px, further ? 3 : 1);
    if (!t) {
      left_out.push_back(a.tip);
      continue;
    }
    // Later names keep a gap from this one (a quarter line): names that touch read as one word ("Lω").
    const Box b = text_box(*t);
    const float gap = 0.25f * label_px;
    for (Obstacles* x : {&roomy, &o}) x->taken.push_back({b.x0 - gap, b.y0 - gap, b.x1 + gap, b.y1 + gap});
    view.texts.push_back(std::move(*t));
  }
  return left_out;
}

}  // namespace tumble::viz
