// A view's key: each drawn element with its colour and meaning, stacked in a
// column on a pale backdrop (GL-free: text items the renderer draws as is).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "viz/draw_list.hpp"
#include "viz/palette.hpp"
#include "viz/text_layout.hpp"

namespace tumble::viz {

/// How an element looks in the key: a line (curves, arrows), a dot or a block (bodies).
enum class Swatch { line, dot, block };

struct KeyEntry {
  Swatch swatch;
  std::vector<Color> colors;  ///< one swatch each (e.g. the three axes on one line)
  std::string text;           ///< its meaning, e.g. "L, angular momentum"
};

/// The entry of a palette meaning (its colour, its usual swatch), with `text`.
KeyEntry key_entry(Meaning m, std::string text);

struct DrawOptions;

/// The key of a view of bodies: the axes, L and ω as drawn (`d`), then each
/// body by name in its colour.
std::vector<KeyEntry> bodies_key(const DrawOptions& d, const std::vector<std::pair<std::string, Color>>& bodies);

/// Size of the key's backdrop for `entries` at `size_px`, px.
glm::vec2 key_size(const std::vector<KeyEntry>& entries, float size_px);

/// Adds the key with its backdrop's top-left corner at `top_left` (viewport
/// px) and returns the backdrop's box.
Box add_key(View& view, const std::vector<KeyEntry>& entries, glm::vec2 top_left, float size_px);

/// Adds the key at the top-right corner of a `width_px` wide view, `top_px`
/// below its top, and returns its box.
Box add_key_top_right(View& view, const std::vector<KeyEntry>& entries, float width_px, float top_px, float size_px);

/// Keys need glyphs this tall, px, to be read at all: in a frame whose key
/// text (2.4 % of its height) is smaller, below 334 px high, keys are left out.
inline constexpr float kMinKeyPx = 8.0f;

/// Where a view's key goes, decided once per video (compose::ExplainViews), so it never jumps.
struct KeySpot {
  glm::vec2 top_left{0};  ///< the backdrop's corner, viewport px
  float shift_px = 0;     ///< the view's content moves this far right (< 0: left), away from the key
};

/// What a key must not cover in `view` (width × height px), added to
/// `content`: the bodies' boxes, named points (Π, ω's contact point) and the
/// opaque ball they sit on, named surfaces, the curves a viewer follows
/// (polhode, herpolhode, Π's path); and to `texts`: every text but the keys
/// and the labels (axis and body labels settle around the key).
void keep_clear(const View& view, float width_px, float height_px, std::vector<Box>& content, std::vector<Box>& texts);

/// The first corner of a width × height view (bottom-right, bottom-left,
/// top-right, top-left; below `top_px`, `margin_px` in) where a key of `size`
/// covers none of `fixed` nor of `moving` (the content's boxes, which move
/// with it sideways, away from the key, by up to half the key's width, up to
/// `shift_room_px` and keeping them `margin_px` inside the view); none: nullopt.
std::optional<KeySpot> find_key_spot(glm::vec2 size, float width_px, float height_px, float top_px, float margin_px,
                                     const std::vector<Box>& fixed, const std::vector<Box>& moving,
                                     float shift_room_px);

/// Moves `view`'s camera sideways so that what lies at its target's depth
/// moves `shift_px` right on screen (a `height_px` high view).
void shift_content(View& view, float shift_px, float height_px);

/// `a` with the entries of `b` it does not have yet (same text and colours).
void merge_entries(std::vector<KeyEntry>& a, const std::vector<KeyEntry>& b);

}  // namespace tumble::viz
