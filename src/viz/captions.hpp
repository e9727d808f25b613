// Text of explanatory videos: captions that fade in and out, a title card,
// body-name labels that face the camera (screen text placed at the body's
// projected position) and the overlay line built from switchable items.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "viz/draw_list.hpp"

namespace tumble::viz {

/// Opacity in [0, 1] at video time `tau` of text shown over [start, end]
/// (video s): linear fades of `fade` s (at most a quarter of the span).
float fade_alpha(double tau, double start, double end, double fade = 0.4);

/// Pixel position (top-left origin) of world point `p` seen by `cam` in a
/// width × height viewport, as the renderer projects it; false when behind the camera.
bool project_to_viewport(const Camera& cam, double width_px, double height_px, const glm::dvec3& p, glm::vec2& out);

/// project_to_viewport for many points seen by one camera: its matrices made once.
class ViewportProjection {
 public:
  ViewportProjection(const Camera& cam, double width_px, double height_px);
  bool operator()(const glm::dvec3& p, glm::vec2& out) const;

 private:
  glm::dmat4 clip_from_world_;
  double width_px_, height_px_;
};

/// A caption centred near the bottom of a frame_w × frame_h frame, on a
/// backdrop: one item per line ('\n' breaks and wrapping at 90 % of the width,
/// or narrower to keep `side_px` free at each side, e.g. for the speed badge).
/// `top`: at the frame's top instead of its bottom.
std::vector<TextItem> caption_items(const std::string& text, float alpha, int frame_w, int frame_h, float side_px = 0,
                                    bool top = false);
/// Its first line (with the backdrop of them all).
TextItem caption_item(const std::string& text, float alpha, int frame_w, int frame_h);

/// The title card's own backdrop (the whole frame; no views are drawn on it).
inline constexpr Color kTitleCardBackground{0.12f, 0.15f, 0.21f, 1.0f};

/// Title (and subtitle) centred in the frame, light on kTitleCardBackground, with opacity `alpha`.
std::vector<TextItem> title_items(const std::string& title, const std::string& subtitle, float alpha, int frame_w,
                                  int frame_h);

/// The speed badge at the frame's bottom-right corner while the video does not
/// run in real time (`speed` from scene::speed_text, e.g. "×1/8"); none for "".
/// `as_is`: `speed` is the whole text ("paused", "flip 1 · paused"), without
/// "slow motion" or "fast". The frame layout moves it to its row above the captions.
/// `text_scale`: the scene's ([draw] text_scale).
std::optional<TextItem> speed_badge(const std::string& speed, bool slow, int frame_w, int frame_h, bool as_is,
                                    double text_scale);


}  // namespace tumble::viz
