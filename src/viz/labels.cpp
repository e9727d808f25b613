// Where labels go, decided GL-free from a view's draw list: a body's name
// beside its body, clear of the view's text, the bodies, their arrows and Π.
#include <algorithm>
#include <cmath>

#include "viz/captions.hpp"
#include "viz/text_layout.hpp"

namespace tumble::viz {

std::optional<Box> screen_box(const Camera& camera, float w, float h, const std::vector<glm::dvec3>& points,
                              float pad) {
  const ViewportProjection project(camera, w, h);
  Box b{1e30f, 1e30f, -1e30f, -1e30f};
  for (const glm::dvec3& p : points) {
    glm::vec2 px;
    if (!project(p, px)) continue;
    b = {std::min(b.x0, px.x), std::min(b.y0, px.y), std::max(b.x1, px.x), std::max(b.y1, px.y)};
  }
  // What the view shows of it: clipped to the view (a body beside the camera projects far out).
  b = {std::max(b.x0 - pad, 0.0f), std::max(b.y0 - pad, 0.0f), std::min(b.x1 + pad, w), std::min(b.y1 + pad, h)};
  if (b.x0 < b.x1 && b.y0 < b.y1) return b;
  return std::nullopt;
}

bool is_label(const TextItem& t) { return t.name.rfind("label", 0) == 0 || t.name.rfind("axis_label", 0) == 0; }

namespace {

Box grown(const Box& b, float g) { return {b.x0 - g, b.y0 - g, b.x1 + g, b.y1 + g}; }

bool has_subject(const TextItem& t) { return t.subject_px.z > t.subject_px.x; }

// Named points (the Π dot) on screen: ± 3 % of the view's height, or
// (`as_drawn`) as large as they are drawn.
std::vector<Box> point_boxes(const View& view, float w, float h, bool as_drawn) {
  std::vector<Box> out;
  const glm::dvec3 right = glm::normalize(glm::cross(view.camera.target - view.camera.position, view.camera.up));
  for (const PointItem& p : view.points) {
    glm::vec2 c, edge;
    if (p.name.empty() || !project_to_viewport(view.camera, w, h, p.position, c)) continue;
    float r = 0.03f * h;
    if (as_drawn && project_to_viewport(view.camera, w, h, p.position + p.radius * right, edge)) r = glm::length(edge - c);
    out.push_back({c.x - r, c.y - r, c.x + r, c.y + r});
  }
  return out;
}

// What no label covers: the other text and its backdrops, and (`points`) the named points' wide boxes.
std::vector<Box> text_obstacles(const View& view, float w, float h, bool points = true) {
  std::vector<Box> taken = points ? point_boxes(view, w, h, false) : std::vector<Box>{};
  for (const TextItem& t : view.texts)
    if (!is_label(t)) {
      taken.push_back(text_box(t));
      if (t.backdrop.a > 0) taken.push_back({t.backdrop_px.x, t.backdrop_px.y, t.backdrop_px.z, t.backdrop_px.w});
    }
  return taken;
}

// What every label also keeps clear of: every body's box, the named curves and
// each arrow as short pieces along it (a slanted arrow's own box would cover its sides).
std::vector<Box> solid_obstacles(const View& view, float w, float h) {
  std::vector<Box> out;
  for (const BoxItem& b : view.boxes)
    if (const auto s = screen_box(view.camera, w, h, box_corners(b))) out.push_back(*s);
  // The curves a viewer follows (named), segment by segment.
  for (const PolylineItem& l : view.polylines)
    if (!l.name.empty())
      for (std::size_t i = 1; i < l.points.size(); ++i)
        if (const auto s = screen_box(view.camera, w, h, {l.points[i - 1], l.points[i]}, 1.5f)) out.push_back(*s);
  constexpr int kPieces = 12;
  for (const ArrowItem& a : view.arrows)
    for (int i = 0; i < kPieces; ++i) {
      const glm::dvec3 p0 = a.origin + a.vector * (static_cast<double>(i) / kPieces);
      const glm::dvec3 p1 = a.origin + a.vector * (static_cast<double>(i + 1) / kPieces);
      if (const auto s = screen_box(view.camera, w, h, {p0, p1}, 2.0f)) out.push_back(*s);
    }
  return out;
}

// A body's label around its subject: above, below, right, left, then the
// corners, each a line further out in turn.
std::vector<glm::vec2> around(const glm::vec4& s, glm::vec2 size, float gap) {
  const float cx = 0.5f * (s.x + s.z - size.x), cy = 0.5f * (s.y + s.w - size.y);
  std::vector<glm::vec2> out;
  for (int ring = 0; ring < 4; ++ring) {
    const float g = gap + static_cast<float>(ring) * size.y;
    const float above = s.y - g - size.y, below = s.w + g, right = s.z + g, left = s.x - g - size.x;
    out.insert(out.end(), {{cx, above}, {cx, below}, {right, cy}, {left, cy},
                           {right, above}, {left, above}, {right, below}, {left, below}});
  }
  return out;
}

// Any other label near its place: up or down by up to two lines, then beside
// it; then, as a last resort, a little further (an axis' end must keep its name).
std::vector<glm::vec2> nearby(glm::vec2 at, glm::vec2 size, float line) {
  std::vector<glm::vec2> out;
  for (float dx : {0.0f, 0.7f, -0.7f})
    for (float dy : {0.0f, 1.1f, -1.1f, 2.2f, -2.2f}) out.push_back(at + glm::vec2(dx * size.x, dy * line));
  for (float dx : {0.0f, 1.4f, -1.4f, 0.7f, -0.7f, 2.1f, -2.1f})
    for (float dy : {3.3f, -3.3f, 1.1f, -1.1f, 0.0f})
      if (std::abs(dx) > 1.0f || std::abs(dy) > 3.0f) out.push_back(at + glm::vec2(dx * size.x, dy * line));
  return out;
}

}  // namespace

bool is_pinned_label(const TextItem& t) { return t.name.rfind("label", 0) == 0; }

std::vector<Box> label_obstacles(const View& view, float w, float h) {
  std::vector<Box> out = text_obstacles(view, w, h);
  const std::vector<Box> solid = solid_obstacles(view, w, h);
  out.insert(out.end(), solid.begin(), solid.end());
  for (const TextItem& t : view.texts)
    if (has_subject(t)) out.push_back({t.subject_px.x, t.subject_px.y, t.subject_px.z, t.subject_px.w});
  return out;
}

Occupancy::Occupancy(int w, int h)
    : w_(std::max(w, 1)), h_(std::max(h, 1)), n_(static_cast<std::size_t>(w_ + 1) * static_cast<std::size_t>(h_ + 1), 0) {}

void Occupancy::add(const Box& b) {
  // Whole pixels touched, clipped to the view; +1 at the top-left, -1 past the other corners.
  const int x0 = std::clamp(static_cast<int>(std::floor(b.x0)), 0, w_), x1 = std::clamp(static_cast<int>(std::ceil(b.x1)), 0, w_);
  const int y0 = std::clamp(static_cast<int>(std::floor(b.y0)), 0, h_), y1 = std::clamp(static_cast<int>(std::ceil(b.y1)), 0, h_);
  if (x0 >= x1 || y0 >= y1) return;
  const auto cell = [&](int x, int y) -> int& { return n_[static_cast<std::size_t>(y) * static_cast<std::size_t>(w_ + 1) + static_cast<std::size_t>(x)]; };
  ++cell(x0, y0), --cell(x1, y0), --cell(x0, y1), ++cell(x1, y1);
}

void Occupancy::seal() {
  const std::size_t row = static_cast<std::size_t>(w_ + 1);
  // Coverage per pixel (prefix sums of the differences), then 1 where covered, then its summed area.
  for (int pass = 0; pass < 2; ++pass) {
    for (int y = 0; y <= h_; ++y)
      for (int x = 1; x <= w_; ++x) n_[y * row + x] += n_[y * row + x - 1];
    for (int y = 1; y <= h_; ++y)
      for (int x = 0; x <= w_; ++x) n_[y * row + x] += n_[(y - 1) * row + x];
    if (pass == 0)
      for (int& c : n_) c = c > 0 ? 1 : 0;
  }
}

bool Occupancy::clear(const Box& b) const {
  if (b.x0 < 0 || b.y0 < 0 || b.x1 > static_cast<float>(w_) || b.y1 > static_cast<float>(h_)) return false;
  const int x0 = static_cast<int>(std::floor(b.x0)), x1 = static_cast<int>(std::ceil(b.x1));
  const int y0 = static_cast<int>(std::floor(b.y0)), y1 = static_cast<int>(std::ceil(b.y1));
  // Summed area over pixels [x0, x1) × [y0, y1): entry (x, y) sums pixels left of x and above y, inclusive of x, y.
  const auto sum = [&](int x, int y) { return x <= 0 || y <= 0 ? 0 : at(x - 1, y - 1); };
  return sum(x1, y1) - sum(x0, y1) - sum(x1, y0) + sum(x0, y0) == 0;
}

std::optional<glm::vec2> clear_spot(const Box& near, glm::vec2 size, float gap, const Occupancy& taken,
                                    const std::vector<Box>& also) {
  const auto free = [&](glm::vec2 p) {
    const Box b = grown({p.x, p.y, p.x + size.x, p.y + size.y}, gap);
    return taken.clear(b) && std::none_of(also.begin(), also.end(), [&](const Box& o) { return o.overlaps(b); });
  };
  for (const glm::vec2 p : around({near.x0, near.y0, near.x1, near.y1}, size, gap))
    if (free(p)) return p;
  // Then a grid over the whole view, nearest to the subject first.
  const glm::vec2 centre{0.5f * (near.x0 + near.x1 - size.x), 0.5f * (near.y0 + near.y1 - size.y)};
  std::optional<glm::vec2> best;
  float best_d = 1e30f;
  const float step = std::max(2.0f, 0.25f * size.y);
  for (float y = gap; y + size.y + gap <= taken.height(); y += step)
    for (float x = gap; x + size.x + gap <= taken.width(); x += step) {
      if (!free({x, y})) continue;
      const float d = glm::dot(glm::vec2(x, y) - centre, glm::vec2(x, y) - centre);
      if (d < best_d) best_d = d, best = glm::vec2(x, y);
    }
  return best;
}

namespace {

// Whether `b` lies on the face of the ball drawn at `ball` (centre x, y, radius).
bool on_ball(const glm::vec3& ball, const Box& b) {
  const glm::vec2 near{std::clamp(ball.x, b.x0, b.x1), std::clamp(ball.y, b.y0, b.y1)};
  return glm::length(near - glm::vec2(ball)) < ball.z;
}

}  // namespace

std::vector<TextItem> settle_labels(View& view, float width_px, float height_px, const std::vector<Box>& also_clear) {
  const std::optional<glm::vec3>& ball = view.ball_px;
  std::vector<Box> taken = text_obstacles(view, width_px, height_px);
  taken.insert(taken.end(), also_clear.begin(), also_clear.end());
  // An axis end's name keeps a quarter line from the other text but may come up
  // to Π's dot as drawn (never over it): near the view's edge a sphere's tip,
  // with Π passing it, has no other place within a few lines.
  std::vector<Box> taken_by_axes = text_obstacles(view, width_px, height_px, false);
  taken_by_axes.insert(taken_by_axes.end(), also_clear.begin(), also_clear.end());
  const std::vector<Box> dots = point_boxes(view, width_px, height_px, true);
  const bool labels = std::any_of(view.texts.begin(), view.texts.end(), is_label);
  const std::vector<Box> solid = labels ? solid_obstacles(view, width_px, height_px) : std::vector<Box>{};
  std::vector<TextItem> kept, left_out;
  for (TextItem& t : view.texts) {
    if (!is_label(t)) {
      kept.push_back(std::move(t));
      continue;
    }
    // A quarter line apart from everything, so that two labels never crowd into one.
    const float gap = 0.25f * t.size_px;
    const Box at = text_box(t);
    const glm::vec2 size{at.x1 - at.x0, at.y1 - at.y0};
    const bool subject = has_subject(t);
    const Box own{t.subject_px.x, t.subject_px.y, t.subject_px.z, t.subject_px.w};
    bool placed = false;
    for (const glm::vec2 p : subject ? around(t.subject_px, size, gap) : nearby(t.position_px, size, t.size_px)) {
      const Box b{p.x, p.y, p.x + size.x, p.y + size.y};
      if (b.x0 < 0 || b.y0 < 0 || b.x1 > width_px || b.y1 > height_px) continue;
      const Box wide = grown(b, gap);
      const auto hit = [&](const Box& o) { return o.overlaps(wide); };
      if (is_pinned_label(t) ? std::any_of(taken.begin(), taken.end(), hit)
                             : std::any_of(taken_by_axes.begin(), taken_by_axes.end(), hit) ||
                                   std::any_of(dots.begin(), dots.end(), [&](const Box& o) { return o.overlaps(b); }))
        continue;
      if ((subject && own.overlaps(wide)) || std::any_of(solid.begin(), solid.end(), hit)) continue;
      // An axis end's name moves beside the ball, never onto its face (kept where it was put if nowhere else).
      if (ball && t.name.rfind("axis_label", 0) == 0 && !on_ball(*ball, at) && on_ball(*ball, b)) continue;
      t.position_px = p;
      taken.push_back(b);
      taken_by_axes.push_back(b);
      kept.push_back(std::move(t));
      placed = true;
      break;
    }
    // An axis end must keep its name: with no clear place, where it was put (beside its tip).
    if (!placed && t.name.rfind("axis_label", 0) == 0) kept.push_back(std::move(t));
    else if (!placed) left_out.push_back(std::move(t));
  }
  view.texts = std::move(kept);
  return left_out;
}

}  // namespace tumble::viz
