// Where each view of a DrawList lands in the frame, and its camera matrices.
// Header-only and GL-free so tests can project points exactly as the
// renderer does.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "viz/draw_list.hpp"

namespace tumble::compose {

/// A viewport in pixels with a top-left origin (image convention).
struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;
  float aspect() const { return height > 0 ? float(width) / float(height) : 1.0f; }
};

/// Cell `index` of `count` views on a grid of `columns` (row-major) covering
/// a frame_w x frame_h frame. Cells tile the frame exactly; cells not in the
/// first row/column give up a 1 px top/left strip as a visible separator.
inline PixelRect view_rect(int index, int count, int columns, int frame_w, int frame_h) {
  const int cols = std::max(1, std::min(columns, std::max(count, 1)));
  const int rows = std::max(1, (count + cols - 1) / cols);
  const int c = index % cols, r = index / cols;
  const int x0 = c * frame_w / cols, x1 = (c + 1) * frame_w / cols;
  const int y0 = r * frame_h / rows, y1 = (r + 1) * frame_h / rows;
  const int gap_x = c > 0 ? 1 : 0, gap_y = r > 0 ? 1 : 0;
  return {x0 + gap_x, y0 + gap_y, x1 - x0 - gap_x, y1 - y0 - gap_y};
}

/// Where view `index` lands: its own viewport (fractions of the frame) when
/// it has one, else its cell of the grid.
inline PixelRect view_rect(const viz::View& view, int index, int count, int columns, int frame_w, int frame_h) {
  if (!view.viewport) return view_rect(index, count, columns, frame_w, frame_h);
  const glm::dvec4 f = *view.viewport;
  const int x0 = int(std::lround(f.x * frame_w)), y0 = int(std::lround(f.y * frame_h));
  const int x1 = int(std::lround((f.x + f.z) * frame_w)), y1 = int(std::lround((f.y + f.w) * frame_h));
  const int gap_x = x0 > 0 ? 1 : 0, gap_y = y0 > 0 ? 1 : 0;  // separator, as on the grid
  return {x0 + gap_x, y0 + gap_y, x1 - x0 - gap_x, y1 - y0 - gap_y};
}

/// Where view `view`'s 3D content lands, frame px: its content rectangle
/// (View::content_px) inside `rect`, else all of `rect`.
inline PixelRect content_rect(const viz::View& view, const PixelRect& rect) {
  if (!view.content_px) return rect;
  const glm::vec4 c = *view.content_px;
  const int x0 = std::clamp(int(std::lround(c.x)), 0, rect.width), y0 = std::clamp(int(std::lround(c.y)), 0, rect.height);
  const int x1 = std::clamp(int(std::lround(c.z)), x0, rect.width), y1 = std::clamp(int(std::lround(c.w)), y0, rect.height);
  return {rect.x + x0, rect.y + y0, x1 - x0, y1 - y0};
}

/// The size `t` is drawn at in a viewport `width_px` wide, its line `width`
/// px at t.size_px. Named text (explanatory views) is laid out to fit and is
/// drawn as is, so the layout report's boxes are what is drawn; unnamed text
/// (the classic overlay) that would run past the right edge (keeping its left
/// margin, up to 12 px, on the right too) shrinks instead of being clipped: a
/// label in the middle of a view keeps its size.
inline float fitted_text_px(const viz::TextItem& t, float width_px, float width) {
  if (!t.name.empty()) return t.size_px;
  const float left = std::max(t.position_px.x, 0.0f);
  const float room = width_px - left - std::min(left, 12.0f);
  return width > room && room > 0 ? t.size_px * room / width : t.size_px;
}

struct CameraMatrices {
  glm::mat4 view;
  glm::mat4 proj;
};

inline CameraMatrices camera_matrices(const viz::Camera& cam, float aspect) {
  const glm::mat4 view = glm::lookAt(glm::vec3(cam.position), glm::vec3(cam.target), glm::vec3(viz::view_up(cam)));
  const float hh = float(cam.ortho_half_height);
  const glm::mat4 proj =
      hh > 0 ? glm::ortho(-hh * aspect, hh * aspect, -hh, hh, float(cam.near_m), float(cam.far_m))
             : glm::perspective(glm::radians(float(cam.fov_y_deg)), aspect, float(cam.near_m),
                                float(cam.far_m));
  return {view, proj};
}

/// Projects a world point to pixel coordinates (top-left origin, x right,
/// y down) inside the frame, for the view occupying `rect`.
inline glm::vec2 project_to_pixel(const viz::Camera& cam, const PixelRect& rect,
                                  const glm::dvec3& world) {
  const CameraMatrices m = camera_matrices(cam, rect.aspect());
  const glm::vec4 clip = m.proj * m.view * glm::vec4(glm::vec3(world), 1.0f);
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  return {float(rect.x) + (ndc.x * 0.5f + 0.5f) * float(rect.width),
          float(rect.y) + (0.5f - ndc.y * 0.5f) * float(rect.height)};
}

}  // namespace tumble::compose
