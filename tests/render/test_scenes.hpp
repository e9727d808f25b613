// Draw lists shared by the render tests.
#pragma once

#include "viz/draw_list.hpp"

namespace tumble::render::test {

/// One view: red/green/blue unit arrows along x/y/z from the origin.
viz::DrawList axis_arrows();

/// 2x2 views exercising every item kind (boxes, arrows, points, trails,
/// grids, labels, overlay text); used for determinism and visual checks.
viz::DrawList showcase();

}  // namespace tumble::render::test
