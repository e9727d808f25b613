#include "viz/captions.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace tumble::viz {

LabelMetrics view_label_metrics(float height_px) {
  const float size = std::clamp(height_px * 0.055f, 11.0f, 26.0f);
  const float pad = std::round(size * 0.6f);
  return {size, pad, pad * 0.6f, pad * 0.6f + 1.25f * size};
}

float fade_alpha(double tau, double start, double end, double fade) {
  if (tau < start || tau > end) return 0.0f;
  const double f = std::min(fade, 0.25 * (end - start));
  if (f <= 0) return 1.0f;
  return static_cast<float>(std::clamp(std::min(tau - start, end - tau) / f, 0.0, 1.0));
}

bool project_to_viewport(const Camera& cam, double width_px, double height_px, const glm::dvec3& p, glm::vec2& out) {
  const double aspect = width_px / std::max(height_px, 1.0);
  const glm::dmat4 view = glm::lookAt(cam.position, cam.target, cam.up);
  const double hh = cam.ortho_half_height;
  const glm::dmat4 proj = hh > 0 ? glm::ortho(-hh * aspect, hh * aspect, -hh, hh, cam.near_m, cam.far_m)
                                 : glm::perspective(glm::radians(cam.fov_y_deg), aspect, cam.near_m, cam.far_m);
  const glm::dvec4 clip = proj * view * glm::dvec4(p, 1.0);
  if (clip.w <= 0) return false;
  out = {static_cast<float>((clip.x / clip.w * 0.5 + 0.5) * width_px),
         static_cast<float>((0.5 - clip.y / clip.w * 0.5) * height_px)};
  return true;
}

float approx_text_width(const std::string& text, float size_px) {
  // UTF-8 continuation bytes do not advance.
  const auto glyphs = std::count_if(text.begin(), text.end(), [](char c) { return (c & 0xC0) != 0x80; });
  return 0.52f * size_px * static_cast<float>(glyphs);
}

TextItem caption_item(const std::string& text, float alpha, int frame_w, int frame_h) {
  const float size = std::clamp(static_cast<float>(frame_h) / 26.0f, 12.0f, 34.0f);
  const float w = approx_text_width(text, size);
  const float x = std::max(8.0f, 0.5f * (static_cast<float>(frame_w) - w));
  return {text, {x, static_cast<float>(frame_h) - 2.4f * size}, size, {0.08f, 0.09f, 0.12f, alpha}};
}

std::vector<TextItem> title_items(const std::string& title, const std::string& subtitle, float alpha, int frame_w,
                                  int frame_h) {
  std::vector<TextItem> out;
  const float big = std::clamp(static_cast<float>(frame_h) / 12.0f, 16.0f, 72.0f), small = big * 0.5f;
  const float fw = static_cast<float>(frame_w), fh = static_cast<float>(frame_h);
  out.push_back({title, {std::max(8.0f, 0.5f * (fw - approx_text_width(title, big))), 0.38f * fh}, big,
                 {0.97f, 0.97f, 0.98f, alpha}});
  if (!subtitle.empty())
    out.push_back({subtitle, {std::max(8.0f, 0.5f * (fw - approx_text_width(subtitle, small))), 0.38f * fh + 1.5f * big},
                   small, {0.78f, 0.82f, 0.90f, alpha}});
  return out;
}

std::optional<TextItem> speed_badge(const std::string& speed, bool slow, int frame_w, int frame_h) {
  if (speed.empty()) return std::nullopt;
  const std::string text = speed + (slow ? " slow motion" : " fast");
  const float size = std::max(12.0f, static_cast<float>(frame_h) / 36.0f);
  // Bottom-right, below the caption line (caption_item: top at h − 2.4 of its size h/26).
  const float x = static_cast<float>(frame_w) - approx_text_width(text, size) - 0.8f * size;
  return TextItem{text, {x, static_cast<float>(frame_h) - 1.3f * size}, size, {0.70f, 0.12f, 0.10f, 1.0f}};
}

}  // namespace tumble::viz
