// An axis pointing at the viewer drawn as a textbook draws a vector out of
// the page, ⊙: a ring round its tip, so the end-on arrow reads as an axis
// coming towards the eye, not as a blob on the sphere. GL-free.
#pragma once

#include "viz/draw_list.hpp"

namespace tumble::viz {

/// Within this angle of the line of sight an axis end gets its full ring; it
/// fades out by kEndOnFadeDeg, so a turning camera never makes it jump.
inline constexpr double kEndOnDeg = 12, kEndOnFadeDeg = 22;

/// Rings (polylines named "end_on_e1", "end_on_-e3", ...) of radius `radius`
/// round each axis end at `reach` from the centre that points at `view`'s
/// camera, in the axis' colour, in the picture plane.
void add_end_on_marks(View& view, double reach, double radius);

}  // namespace tumble::viz
