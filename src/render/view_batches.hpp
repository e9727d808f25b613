// Turns one viz::View into GPU-ready batches: per-instance transforms for the
// unit meshes and coloured line vertices. GL-free, so it is cheap to test and
// keeps the Renderer itself about draw order and state only.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "render/instanced_mesh.hpp"
#include "render/line_pass.hpp"
#include "render/sphere_pass.hpp"
#include "viz/draw_list.hpp"

namespace tumble::render {

struct Polyline {
  std::vector<LineVertex> strip;  ///< alpha already faded oldest -> newest
  float width_px;
  bool over_glass = false;        ///< drawn after the translucent surfaces
};

struct ViewBatches {
  std::vector<MeshInstance> arrow_shafts;  ///< unit cylinder instances
  std::vector<MeshInstance> arrow_heads;   ///< unit cone instances
  std::vector<SphereInstance> spheres;     ///< particle impostors
  std::vector<MeshInstance> boxes;         ///< unit cube, sorted far -> near
  std::vector<LineVertex> box_edges;       ///< GL_LINES pairs
  std::vector<LineVertex> grid;            ///< GL_LINES pairs
  std::vector<Polyline> polylines;
};

/// Boxes are ordered back to front as seen from the view's camera.
ViewBatches build_view_batches(const viz::View& view);

}  // namespace tumble::render
