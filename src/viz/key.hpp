// A view's key: each drawn element with its colour and meaning, stacked in a
// column on a pale backdrop (GL-free: text items the renderer draws as is).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "viz/draw_list.hpp"
#include "viz/palette.hpp"
#include "viz/text_layout.hpp"

namespace tumble::viz {

/// How an element looks in the key: a line (curves, arrows), a dot, a block (bodies) or an arrow.
/// `trail`: a line drawn unbroken, its colours end to end (a trail is no dashed line).
enum class Swatch { line, dot, block, arrow, trail };

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
/// `arrows`: arrows (the axes, L, ω) keyed by arrows and the trails by faded
/// lines, so the two never share a swatch (else both by lines, as before).
std::vector<KeyEntry> bodies_key(const DrawOptions& d, const std::vector<std::pair<std::string, Color>>& bodies,
                                 bool arrows = false);

/// Size of the key's backdrop for `entries` at `size_px`, px.
glm::vec2 key_size(const std::vector<KeyEntry>& entries, float size_px);

/// Adds the key with its backdrop's top-left corner at `top_left` (viewport
/// px) and returns the backdrop's box.
Box add_key(View& view, const std::vector<KeyEntry>& entries, glm::vec2 top_left, float size_px);

/// A key laid out in rows across `max_width_px` (entries left to right, a
/// new row when the next does not fit; each row centred): what
/// key_row_lines and add_key_row share.
struct KeyRows {
  std::vector<std::vector<std::size_t>> rows;  ///< entry indices per row
  glm::vec2 size{0};                           ///< the backdrop's size, px
};
KeyRows key_rows(const std::vector<KeyEntry>& entries, float size_px, float max_width_px);

/// Adds the key in rows (key_rows) centred on `centre_x`, its backdrop's top
/// at `top` (px of the texts' frame), to `texts`; returns the backdrop's box.
Box add_key_row(std::vector<TextItem>& texts, const std::vector<KeyEntry>& entries, float centre_x, float top,
                float size_px, float max_width_px);

/// Whether two entries are the same (swatch, colours and text).
bool same_entry(const KeyEntry& a, const KeyEntry& b);

/// Keys need glyphs this tall, px, to be read at all: in a frame whose key
/// text (2.4 % of its height) is smaller, below 334 px high, keys are left out.
inline constexpr float kMinKeyPx = 8.0f;

}  // namespace tumble::viz
