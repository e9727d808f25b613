// One row per view kind: the kind, as the scene reader names it, and the maker
// of its panel (one file per kind under compose/views/).
#include <array>

#include "compose/panel.hpp"
#include "compose/views/kinds.hpp"

namespace tumble::compose {

namespace {

struct ViewKindRow {
  scene::ViewKind kind;
  std::unique_ptr<Panel> (*make)(const PanelContext&, std::size_t);
};

constexpr std::array<ViewKindRow, 5> kViewKinds = {{
    {scene::ViewKind::world, make_world},
    {scene::ViewKind::body_frame, make_body_frame},
    {scene::ViewKind::momentum_sphere, make_momentum_sphere},
    {scene::ViewKind::plot, make_plot},
    {scene::ViewKind::poinsot, make_poinsot},
}};

}  // namespace

std::unique_ptr<Panel> make_panel(const PanelContext& ctx, std::size_t index) {
  const scene::ViewKind kind = ctx.scene.render.explain.views[index].kind;
  for (const ViewKindRow& row : kViewKinds)
    if (row.kind == kind) return row.make(ctx, index);
  return make_world(ctx, index);  // unreachable: the reader knows only these kinds
}

std::size_t view_body(const PanelContext& ctx, std::size_t index) {
  const scene::Body* b = ctx.scene.find_body(ctx.scene.render.explain.views[index].body);
  return b ? static_cast<std::size_t>(b - ctx.scene.bodies.data()) : 0;
}

long last_frame(const scene::Run& run, long k) { return std::min(k, static_cast<long>(run.frames.size()) - 1); }

}  // namespace tumble::compose
