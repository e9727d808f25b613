// Text sizes and boxes, GL-free: the sizes of the text roles in proportion to
// the frame's height (a 1080p frame looks like the 540p one, scaled), the ink a
// string covers as the renderer draws it (viz/font_metrics.hpp), greedy wrapping
// and the box a TextItem covers, so layout can be checked without a GL context.
#pragma once

#include <optional>
#include <string>
#include <vector>
#include <string_view>

#include "viz/draw_list.hpp"
#include "viz/palette.hpp"

namespace tumble::viz {

/// What a piece of text is for; one size per role in every view kind.
enum class TextRole { title, subtitle, caption, view_title, key, label, tick, badge };

/// Height of `role`'s text, px, in a frame `frame_h` px high (fractions of
/// it), times the scene's `scale` ([draw] text_scale): every role but the
/// title card's and the captions', which are sized for a hall already.
float text_px(TextRole role, int frame_h, double scale);

/// The horizontal ink of `text` at `size_px` drawn with its pen starting at
/// x = 0: from the leftmost outline edge to the rightmost of any line, px
/// (viz/font_metrics.hpp: the renderer's font at the renderer's scale).
struct InkSpan {
  float x0 = 0, x1 = 0;
  float width() const { return x1 - x0; }
};
InkSpan text_ink(std::string_view text, float size_px);

/// Width of `text`'s ink at `size_px`, px ('\n' breaks lines): what is drawn.
float text_width(std::string_view text, float size_px);

/// The pen's x that centres `text`'s ink on `centre_px`, or ends it at `right_px`.
float centred_x(std::string_view text, float size_px, float centre_px);
float right_aligned_x(std::string_view text, float size_px, float right_px);

/// Number of lines of `text` ('\n' separated).
int text_lines(std::string_view text);

/// `text` with line breaks added between words so that no line is wider than
/// `max_width_px` (a single word wider than that stays whole); '\n' kept.
std::string wrap_text(std::string_view text, float size_px, float max_width_px);

/// An axis-aligned box in pixels: x0, y0 top-left, x1, y1 bottom-right.
struct Box {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
  float area() const { return (x1 - x0) * (y1 - y0); }
};

/// The box `t` covers at its size: its ink across, its lines (size_px each) down.
Box text_box(const TextItem& t);

}  // namespace tumble::viz


namespace tumble::viz {

/// True for text that names a moving thing (names starting "label" or
/// "axis_label"): it may move to stay clear of the view's other text.
bool is_label(const TextItem& t);

/// Places each label of `view` (width × height px) where it overlaps no
/// other text, backdrop, named point (the Π dot, ± 3 % of the view's height)
/// or earlier label, nor any of `also_clear` (e.g. the frame's captions, in
/// the view's pixels), and stays inside the view; a label with no such place is
/// left out. Every label keeps clear of every body's box and arrow. A label
/// with a subject (TextItem::subject_px, a body's box) is tried around it
/// (above, below, right, left, then the corners, stepping out); others move
/// up or down by up to two lines, then sideways. Returns the labels left out.
std::vector<TextItem> settle_labels(View& view, float width_px, float height_px, const std::vector<Box>& also_clear = {});

/// True for a label placed once for a whole run (viz::clear_spot): a body's
/// name ("label:<body>") and a curve's or plane's ("label_polhode", ...), not an axis end's.
bool is_pinned_label(const TextItem& t);

/// What a label placed for a whole run keeps clear of in one frame of `view`:
/// what settle_labels keeps every label clear of, and every label's subject.
std::vector<Box> label_obstacles(const View& view, float width_px, float height_px);

/// Which pixels of a width × height view any of many boxes cover (a run's
/// obstacles, frame after frame): boxes are added, then `seal` counts them
/// once, and `clear` answers for a box in constant time.
class Occupancy {
 public:
  Occupancy(int width_px, int height_px);
  void add(const Box& b);
  void seal();
  bool clear(const Box& b) const;  ///< inside the view and no added box overlaps it
  float width() const { return static_cast<float>(w_); }
  float height() const { return static_cast<float>(h_); }

 private:
  int w_, h_;
  std::vector<int> n_;  // a difference grid, then the summed area of covered pixels
  int at(int x, int y) const { return n_[static_cast<std::size_t>(y) * static_cast<std::size_t>(w_ + 1) + static_cast<std::size_t>(x)]; }
};

/// The first place for a `size` label around `near` (above, below, right,
/// left, corners, stepping out), then anywhere in the view nearest to it,
/// whose box grown by `gap` is clear in `taken` and overlaps none of `also`.
std::optional<glm::vec2> clear_spot(const Box& near, glm::vec2 size, float gap, const Occupancy& taken,
                                    const std::vector<Box>& also = {});

/// Names each arrow of `view` that has a `tip` text at its tip (text named
/// "tip:<arrow name>", in the arrow's colour, `label_px` high): just past its
/// head along the arrow as drawn, else turned a little at a time, clear of
/// every arrow, named curve, opaque surface part, the view's text and the names
/// placed before it (lower `tip_rank` first), inside the width × height view.
/// `further`: where no turn is free, a line or two further out along the same
/// turns. Returns the names with no such place (left out).
std::vector<std::string> label_arrow_tips(View& view, float width_px, float height_px, float label_px, bool further = false);

/// The box `points` cover as `camera` sees them in a width × height view,
/// grown by `pad_px` and clipped to the view; nullopt when none of it shows.
std::optional<Box> screen_box(const Camera& camera, float width_px, float height_px,
                              const std::vector<glm::dvec3>& points, float pad_px = 0);

}  // namespace tumble::viz
