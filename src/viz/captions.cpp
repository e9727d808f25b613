#include "viz/captions.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "viz/palette.hpp"
#include "viz/text_layout.hpp"

namespace tumble::viz {

float fade_alpha(double tau, double start, double end, double fade) {
  if (tau < start || tau > end) return 0.0f;
  const double f = std::min(fade, 0.25 * (end - start));
  if (f <= 0) return 1.0f;
  return static_cast<float>(std::clamp(std::min(tau - start, end - tau) / f, 0.0, 1.0));
}

ViewportProjection::ViewportProjection(const Camera& cam, double width_px, double height_px)
    : width_px_(width_px), height_px_(height_px) {
  const double aspect = width_px / std::max(height_px, 1.0);
  const glm::dmat4 view = glm::lookAt(cam.position, cam.target, view_up(cam));
  const double hh = cam.ortho_half_height;
  const glm::dmat4 proj = hh > 0 ? glm::ortho(-hh * aspect, hh * aspect, -hh, hh, cam.near_m, cam.far_m)
                                 : glm::perspective(glm::radians(cam.fov_y_deg), aspect, cam.near_m, cam.far_m);
  clip_from_world_ = proj * view;
}

bool ViewportProjection::operator()(const glm::dvec3& p, glm::vec2& out) const {
  const glm::dvec4 clip = clip_from_world_ * glm::dvec4(p, 1.0);
  if (clip.w <= 0) return false;
  out = {static_cast<float>((clip.x / clip.w * 0.5 + 0.5) * width_px_),
         static_cast<float>((0.5 - clip.y / clip.w * 0.5) * height_px_)};
  return true;
}

bool project_to_viewport(const Camera& cam, double width_px, double height_px, const glm::dvec3& p, glm::vec2& out) {
  return ViewportProjection(cam, width_px, height_px)(p, out);
}

namespace {

// `text` wrapped to `max_w` (0: 90 % of the frame), each line centred in a
// frame `frame_w` wide with its first line's top at `top`; one backdrop behind them all.
std::vector<TextItem> centred_lines(const std::string& text, float size, Color color, Color backdrop, float frame_w,
                                    float top, const std::string& name, float max_w = 0) {
  const std::string wrapped = wrap_text(text, size, max_w > 0 ? max_w : 0.9f * frame_w);
  std::vector<TextItem> out;
  std::size_t start = 0;
  float y = top, widest = 0;
  while (true) {
    const std::size_t end = wrapped.find('\n', start);
    TextItem t{wrapped.substr(start, end - start), {0, y}, size, color, name};
    widest = std::max(widest, text_width(t.text, size));
    t.position_px.x = std::max(0.02f * frame_w, centred_x(t.text, size, 0.5f * frame_w));
    out.push_back(std::move(t));
    y += size;
    if (end == std::string::npos) break;
    start = end + 1;
  }
  const float pad = 0.35f * size;
  out.front().backdrop = backdrop;
  out.front().backdrop_px = {std::max(0.0f, 0.5f * (frame_w - widest) - 2 * pad), top - pad,
                             std::min(frame_w, 0.5f * (frame_w + widest) + 2 * pad), y + pad};
  return out;
}

}  // namespace

std::vector<TextItem> caption_items(const std::string& text, float alpha, int frame_w, int frame_h, float side_px,
                                    bool at_top) {
  const float size = text_px(TextRole::caption, frame_h, 1), fh = static_cast<float>(frame_h);
  const float fw = static_cast<float>(frame_w);
  // Centred, so lines no wider than this leave `side_px` (and the backdrop's pad) free at each side.
  const float max_w = side_px > 0 ? std::max(0.3f * fw, fw - 2 * (side_px + 0.7f * size)) : 0.9f * fw;
  const int lines = text_lines(wrap_text(text, size, max_w));
  const float top = at_top ? 0.6f * size : fh - static_cast<float>(lines) * size - 0.6f * size;
  return centred_lines(text, size, color_of(Meaning::ink, alpha), {0.99f, 0.99f, 1.0f, 0.92f * alpha}, fw, top,
                       "caption", max_w);
}

TextItem caption_item(const std::string& text, float alpha, int frame_w, int frame_h) {
  return caption_items(text, alpha, frame_w, frame_h).front();
}

std::vector<TextItem> title_items(const std::string& title, const std::string& subtitle, float alpha, int frame_w,
                                  int frame_h) {
  const float big = text_px(TextRole::title, frame_h, 1), small = text_px(TextRole::subtitle, frame_h, 1);
  const float fw = static_cast<float>(frame_w), fh = static_cast<float>(frame_h);
  // On the title card's own backdrop (kTitleCardBackground, the whole frame), light text.
  std::vector<TextItem> out = centred_lines(title, big, {0.97f, 0.97f, 0.98f, alpha}, {0, 0, 0, 0}, fw, 0.36f * fh, "title");
  const float below = out.back().position_px.y + 1.4f * big;
  if (!subtitle.empty())
    for (TextItem& t : centred_lines(subtitle, small, {0.78f, 0.82f, 0.90f, alpha}, {0, 0, 0, 0}, fw, below, "subtitle"))
      out.push_back(std::move(t));
  return out;
}

std::optional<TextItem> speed_badge(const std::string& speed, bool slow, int frame_w, int frame_h, bool as_is,
                                    double text_scale) {
  if (speed.empty()) return std::nullopt;
  const std::string text = as_is ? speed : speed + (slow ? " slow motion" : " fast");
  const float size = text_px(TextRole::badge, frame_h, text_scale);
  // Bottom-right; captions shown with it keep clear of it (caption_items' side_px).
  const float x = right_aligned_x(text, size, static_cast<float>(frame_w) - 0.8f * size);
  return TextItem{text, {x, static_cast<float>(frame_h) - 1.3f * size}, size, {0.70f, 0.12f, 0.10f, 1.0f}, "speed"};
}

}  // namespace tumble::viz
