// A frame laid out like a textbook figure, once per video (docs/architecture.md,
// "Layout rectangles"): the caption strip and the frame key's strip are taken from
// the frame first; each view gets its rectangle of what is left, a title strip
// (title, then the overlay lines), a key strip beside its content and the
// content rectangle, where alone its 3D items are drawn. What does not fit is
// left out and said (FramePlan::notes), never drawn over something else.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "viz/key.hpp"
#include "viz/text_layout.hpp"

namespace tumble::compose {

/// What the layout needs to know of one view.
struct ViewNeeds {
  std::optional<std::array<double, 4>> viewport;  ///< x, y, w, h: fractions of the views' area; none: a grid cell
  std::string kind;                                ///< its kind's name ("world", "plot", ...), for notes
  std::string title;
  int overlay_lines = 0;                           ///< lines under the title (the overlay)
  std::vector<viz::KeyEntry> key;                  ///< its key (none: no key strip)
  bool edge_to_edge = false;                       ///< content without side margins (a plot draws its own)
  bool large_overlay = false;                      ///< overlay lines at the title's size (a comparison's readouts)
};

struct FrameNeeds {
  int width = 0, height = 0;
  double text_scale = 1;             ///< [draw] text_scale (viz::text_px)
  int columns = 1;                   ///< grid of the views without a viewport
  std::vector<ViewNeeds> views;
  std::vector<std::string> captions; ///< every caption's text
  std::string badge;                 ///< the widest status badge's text (speed, a flip's mark; "": none)
  /// Entries of a key for the whole frame, in rows above the captions (a
  /// classic scene's legend), besides those views would repeat.
  std::vector<viz::KeyEntry> frame_key;
  /// Where the caption strip goes. A hook for a declared caption position: top
  /// moves the strip (and the views below it), nothing else changes.
  enum class CaptionSide { bottom, top } caption_side = CaptionSide::bottom;
};

/// Where one view's parts go: `viewport` in frame fractions (render::view_rect
/// turns it into `rect`), the rest in the view's own pixels.
struct ViewPlan {
  glm::dvec4 viewport{0, 0, 1, 1};
  int x = 0, y = 0, width = 0, height = 0;  ///< the view, frame px
  std::string title;                        ///< wrapped to the view
  glm::vec2 title_at{0};                    ///< its pen, view px
  float title_px = 0;
  float overlay_y = 0, overlay_px = 0;      ///< the overlay lines' top, view px, and size
  viz::Box content;                         ///< view px
  std::vector<viz::KeyEntry> key;           ///< what its key strip holds (none: the frame's key has it)
  std::optional<glm::vec2> key_at;          ///< the key backdrop's top-left, view px (none: not drawn)
  float key_px = 0;
};

struct FramePlan {
  std::vector<ViewPlan> views;
  viz::Box captions;        ///< frame px (zero height: none)
  float caption_shift = 0;  ///< px the captions move from their bottom place (a caption strip at the top)
  float badge_side = 0;     ///< px the captions keep free at each side for the badge (0: it has its own row)
  float badge_y = 0;        ///< the badge's top, frame px, in its row at the top of the caption strip
  /// One key for the whole frame, in rows across its own strip above the
  /// captions, when views would repeat each other's entries (zero height: none).
  std::vector<viz::KeyEntry> frame_key;
  viz::Box frame_key_box;   ///< frame px
  bool frame_key_in_corner = false;  ///< in a corner the views leave free, not a strip across the frame
  float frame_key_px = 0;
  /// The views whose keys it holds: drawn while one of them is (a closing
  /// segment's views, with no key, do not show the views' key it replaced),
  /// or always where the frame has a key of its own (a legend).
  std::vector<std::size_t> frame_key_views;
  /// For each frame_key entry, the views whose keys gave it (none: the frame's own legend):
  /// an entry is drawn only while one of them is, so the key lists only what the frame shows.
  std::vector<std::vector<std::size_t>> frame_key_from;
  bool frame_key_always = false;
  std::vector<std::string> notes;  ///< what was left out, where and why
};

FramePlan plan_frame(const FrameNeeds& needs);

/// How notes name view i: "view 1 (momentum_sphere, 'Π on the sphere')".
std::string view_name(std::size_t i, const std::string& kind, const std::string& title);

}  // namespace tumble::compose
