#include "compose/layout_report.hpp"

#include <algorithm>
#include <cmath>

#include "io/json.hpp"
#include "compose/view_layout.hpp"

namespace tumble::compose {

namespace {

// Text fainter than kVisible is not counted as seen (a fading caption); a
// backdrop at least kOpaque hides what lies under it: below kVisible, so
// that a fading title card hides what is under it for as long as it is seen.
constexpr float kVisible = 0.5f, kOpaque = 0.45f;

// Projects `p` into `rect` (frame px); false when behind the camera.
bool project(const CameraMatrices& m, const PixelRect& rect, const glm::dvec3& p, glm::vec2& out) {
  const glm::vec4 clip = m.proj * m.view * glm::vec4(glm::vec3(p), 1.0f);
  if (clip.w <= 0) return false;
  out = {float(rect.x) + (clip.x / clip.w * 0.5f + 0.5f) * float(rect.width),
         float(rect.y) + (0.5f - clip.y / clip.w * 0.5f) * float(rect.height)};
  return true;
}

bool inside(const PixelRect& r, glm::vec2 p) {
  return p.x >= float(r.x) && p.x <= float(r.x + r.width) && p.y >= float(r.y) && p.y <= float(r.y + r.height);
}

// `p` lies behind a larger sphere of the view (the momentum sphere's opaque ball).
bool behind_sphere(const viz::View& v, const glm::dvec3& p, double own_radius) {
  const glm::dvec3 eye = v.camera.position, d = p - eye;
  const double len2 = glm::dot(d, d);
  for (const viz::PointItem& s : v.points) {
    if (s.radius <= own_radius || s.color.a < 1.0f || len2 <= 0) continue;
    const double t = std::clamp(glm::dot(s.position - eye, d) / len2, 0.0, 1.0);
    const glm::dvec3 closest = eye + t * d - s.position;
    if (t < 1.0 && glm::dot(closest, closest) < s.radius * s.radius) return true;
  }
  return false;
}

float covered(const viz::Box& a, const viz::Box& b) {
  const float w = std::min(a.x1, b.x1) - std::max(a.x0, b.x0), h = std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
  return w > 0 && h > 0 ? w * h / std::max(a.area(), 1e-6f) : 0.0f;
}

struct Occluder {
  viz::Box box;
  std::size_t order;  // drawn after the items of lower order
  bool glyphs;        // text: hides markers and curves, not other text (their overlap is what tests look for)
};

viz::Box offset(viz::Box b, const PixelRect& r) {
  return {b.x0 + float(r.x), b.y0 + float(r.y), b.x1 + float(r.x), b.y1 + float(r.y)};
}

// A view's texts (and those over the whole frame, `rect` = the frame).
void add_texts(const std::vector<viz::TextItem>& texts, const std::string& view, const PixelRect& rect,
               std::size_t& order, std::vector<LayoutItem>& out, std::vector<std::size_t>& out_order,
               std::vector<Occluder>& occluders) {
  for (const viz::TextItem& t : texts) {
    ++order;
    if (t.backdrop.a >= kOpaque) {
      const glm::vec4 b = t.backdrop_px;
      occluders.push_back({offset({b.x, b.y, b.z, b.w}, rect), order, false});
    }
    ++order;
    viz::TextItem drawn = t;
    drawn.size_px = fitted_text_px(t, float(rect.width), viz::text_width(t.text, t.size_px));
    LayoutItem item{view, t.name.empty() ? "text" : t.name, t.key ? "key" : "text", offset(viz::text_box(drawn), rect),
                    true, t.text, drawn.size_px, {}};
    const viz::Box& b = item.box;
    const float in_x = std::min(b.x1, float(rect.x + rect.width)) - std::max(b.x0, float(rect.x));
    const float in_y = std::min(b.y1, float(rect.y + rect.height)) - std::max(b.y0, float(rect.y));
    item.visible = t.color.a >= kVisible && !t.text.empty() && in_x > 0.9f * (b.x1 - b.x0) && in_y > 0.9f * (b.y1 - b.y0);
    if (t.color.a >= kVisible && !t.text.empty()) occluders.push_back({b, order, true});
    out.push_back(std::move(item));
    out_order.push_back(order);
  }
}

// The screen radius, px, of a world length `r` at `p` (0 behind the camera).
float screen_radius(const CameraMatrices& m, const PixelRect& rect, const viz::Camera& cam, const glm::dvec3& p, double r) {
  glm::vec2 c, e;
  if (!project(m, rect, p, c) || !project(m, rect, p + r * glm::normalize(cam.up), e)) return 0.0f;
  return glm::length(e - c);
}

// A view's reported 3D items: named points, arrows and polylines, projected
// through its content rectangle `rect`.
void add_scene_items(const viz::View& v, const std::string& view, const PixelRect& rect, std::size_t order,
                     std::vector<LayoutItem>& out, std::vector<std::size_t>& out_order) {
  const CameraMatrices m = camera_matrices(v.camera, rect.aspect());
  auto push = [&](const std::string& name, const char* kind, const std::vector<glm::dvec3>& pts, double radius) {
    viz::Box box{1e30f, 1e30f, -1e30f, -1e30f};
    bool any = false;
    std::vector<glm::vec2> path;
    for (const glm::dvec3& p : pts) {
      glm::vec2 px;
      if (!project(m, rect, p, px)) continue;
      path.push_back(px);
      box = {std::min(box.x0, px.x), std::min(box.y0, px.y), std::max(box.x1, px.x), std::max(box.y1, px.y)};
      any = any || (inside(rect, px) && !behind_sphere(v, p, radius));
    }
    if (box.x0 > box.x1) box = {};
    out.push_back({view, name, kind, box, any, {}, 0, std::move(path)});
    out_order.push_back(order);
  };
  for (const viz::PointItem& p : v.points) {
    if (p.name.empty()) continue;
    // The dot's screen radius: its centre and a point `radius` away along the camera's up.
    glm::vec2 c, e;
    const bool front = project(m, rect, p.position, c) &&
                       project(m, rect, p.position + p.radius * glm::normalize(v.camera.up), e);
    const float r = front ? glm::length(e - c) : 0.0f;
    out.push_back({view, p.name, "marker", {c.x - r, c.y - r, c.x + r, c.y + r},
                   front && inside(rect, c) && !behind_sphere(v, p.position, p.radius), {}, 0, {}});
    out_order.push_back(order);
  }
  for (const viz::BoxItem& b : v.boxes) {  // what the view shows of it: clipped to the view
    push("body", "body", viz::box_corners(b), 0.0);
    viz::Box& c = out.back().box;
    c = {std::max(c.x0, float(rect.x)), std::max(c.y0, float(rect.y)), std::min(c.x1, float(rect.x + rect.width)),
         std::min(c.y1, float(rect.y + rect.height))};
    if (c.x0 >= c.x1 || c.y0 >= c.y1) c = {}, out.back().visible = false;
  }
  // A body drawn as its surface (and the ghost a comparison draws): the extent
  // of its triangles' vertices, as it is drawn (kind "surface").
  for (const viz::SurfaceItem& f : v.surfaces) {
    if (!f.mesh || !(f.name.empty() || f.name == "ghost")) continue;  // named others: a sphere view's ellipsoid
    std::vector<glm::dvec3> pts;
    pts.reserve(f.mesh->positions.size());
    for (const glm::vec3& p : f.mesh->positions) pts.push_back(glm::dvec3(f.model * glm::dvec4(glm::dvec3(p), 1.0)));
    push(f.name.empty() ? "surface" : f.name, "surface", pts, 0.0);
    out.back().path.clear();
  }
  for (const viz::ArrowItem& a : v.arrows) {
    if (a.name.empty()) continue;
    // The whole arrow: its shaft from tail to tip, grown by its head's radius
    // (render::build_view_batches: 2.4 shaft radii) where each end lies.
    push(a.name, "arrow", {a.origin, a.origin + a.vector}, a.radius);
    viz::Box& b = out.back().box;
    const float grow = std::max(screen_radius(m, rect, v.camera, a.origin + a.vector, 2.4 * a.radius),
                                screen_radius(m, rect, v.camera, a.origin, a.radius));
    if (b.x1 > b.x0 || b.y1 > b.y0 || !out.back().path.empty()) b = {b.x0 - grow, b.y0 - grow, b.x1 + grow, b.y1 + grow};
  }
  for (const viz::PolylineItem& l : v.polylines)
    if (!l.name.empty()) push(l.name, "curve", l.points, 0.0);
}

}  // namespace

std::vector<LayoutItem> layout_items(const viz::DrawList& dl, int frame_w, int frame_h) {
  std::vector<LayoutItem> out;
  std::vector<std::size_t> order_of;
  std::vector<Occluder> occluders;
  std::size_t order = 0;
  const int count = static_cast<int>(dl.views.size());
  for (int i = 0; i < count; ++i) {
    const viz::View& v = dl.views[static_cast<std::size_t>(i)];
    const PixelRect rect = view_rect(v, i, count, dl.columns, frame_w, frame_h);
    const PixelRect content = content_rect(v, rect);
    const std::string name = std::to_string(i) + ":" + (v.name.empty() ? "view" : v.name);
    out.push_back({name, "content", "content",
                   {float(content.x), float(content.y), float(content.x + content.width), float(content.y + content.height)},
                   true, {}, 0, {}});
    order_of.push_back(0);
    add_scene_items(v, name, content, ++order, out, order_of);
    add_texts(v.texts, name, rect, order, out, order_of, occluders);
  }
  add_texts(dl.texts, "frame", {0, 0, frame_w, frame_h}, order, out, order_of, occluders);
  for (const std::string& note : dl.notes) {
    const char* what = note.find(": label '") != std::string::npos ? "label"
                       : note.find("key") != std::string::npos   ? "key"
                                                                 : "layout";
    out.push_back({"frame", what, "note", {}, false, note, 0, {}});
    order_of.push_back(0);
  }
  // Whatever a later, opaque enough backdrop (or, for markers and curves, text) covers by half is hidden.
  for (std::size_t j = 0; j < out.size(); ++j)
    for (const Occluder& o : occluders)
      if (o.order > order_of[j] && !(o.glyphs && (out[j].kind == "text" || out[j].kind == "key")) &&
          covered(out[j].box, o.box) >= 0.5f)
        out[j].visible = false;
  return out;
}

void write_layout(std::ostream& out, long frame, const std::vector<LayoutItem>& items) {
  for (const LayoutItem& it : items) {
    io::Json j;
    j["frame"] = frame;
    j["view"] = it.view;
    j["name"] = it.name;
    j["kind"] = it.kind;
    j["box"] = {std::round(it.box.x0 * 10) / 10, std::round(it.box.y0 * 10) / 10, std::round(it.box.x1 * 10) / 10,
                std::round(it.box.y1 * 10) / 10};
    j["visible"] = it.visible;
    if (it.kind == "note") j["text"] = it.text;
    if (it.kind == "arrow" && it.path.size() == 2) {
      j["from"] = {std::round(it.path[0].x * 10) / 10, std::round(it.path[0].y * 10) / 10};
      j["to"] = {std::round(it.path[1].x * 10) / 10, std::round(it.path[1].y * 10) / 10};
    }
    if (it.kind == "text" || it.kind == "key") {
      j["text"] = it.text;
      j["size_px"] = std::round(it.size_px * 100) / 100;
    }
    out << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
  }
}

}  // namespace tumble::compose
