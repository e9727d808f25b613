// Names placed once for a whole run: a body's name, a Poinsot view's
// "polhode" and "herpolhode", put where they stay clear of everything the
// view shows in every frame (beside the body's swept extent), so that they
// never jump from frame to frame as a per-frame placement makes them.
#pragma once

#include <map>
#include <string>

#include <glm/glm.hpp>

#include "compose/panel.hpp"
#include "scene/frame_clock.hpp"

namespace tumble::compose {

/// Where each pinned label (viz::is_pinned_label) of `panel` goes, its
/// top-left in content px, by name: clear of its view's bodies, arrows,
/// named curves, other text and labels' subjects in every frame of `clock`
/// (a label with no such place is left out here and placed frame by frame).
std::map<std::string, glm::vec2> pin_labels(const Panel& panel, const scene::FrameClock& clock, glm::vec2 size_px,
                                            float label_px, bool tip_names_further = false);

/// For each of `pinned` (content px) that names a curve of `view` (TextItem::leader_to)
/// and is not already at it: a leader, a thin line in the curve's colour drawn
/// over the glass, from the label's box to the curve's point nearest to it on screen.
void add_leaders(viz::View& view, const std::vector<viz::TextItem>& pinned, glm::vec2 size_px);

}  // namespace tumble::compose
