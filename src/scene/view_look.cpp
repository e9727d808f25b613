// A view's look options: a world view's trails, box, line widths and tip names;
// a momentum_sphere's ellipsoid, path, level curves and zoom. Errors name kinds that do not take them.
#include <array>
#include <string>

#include "scene/internal.hpp"

namespace tumble::scene::detail {

// A world view's own trail_axes and trails (as [draw]'s, for this view), box (false: no principal-box
// outline), see_through (surfaces faded, axes behind them seen), L_width and omega_width (L's, ω's
// thickness, times) and trail_width (the trails' width, times: a small view's wobble reads bold).
static void read_world_look(TableReader& r, ViewConfig& v) {
  for (std::string_view key : {"trail_axes", "box", "trails", "see_through", "L_width", "omega_width", "trail_width"})
    if (r.has(key) && v.kind != ViewKind::world) r.error(key, "only a world view takes " + std::string(key));
  v.box = r.boolean("box").value_or(true);
  v.trail_seconds = r.number("trails", Range::closed(0, 1e4));
  v.see_through = r.boolean("see_through").value_or(false);
  v.L_width = r.number("L_width", Range::closed(0.25, 4)).value_or(1);
  v.omega_width = r.number("omega_width", Range::closed(0.25, 4)).value_or(1);
  v.trail_width = r.number("trail_width", Range::closed(0.25, 4)).value_or(1);
  const auto axes = r.strings("trail_axes");
  if (!axes) return;
  std::array<bool, 3> on = {false, false, false};
  for (const std::string& a : *axes) {
    if (a == "e1" || a == "e2" || a == "e3") on[static_cast<std::size_t>(a[1] - '1')] = true;
    else r.error("trail_axes", "expected items from \"e1\", \"e2\", \"e3\", found " + quote_token(a));
  }
  v.trail_axes = on;
}

// A momentum_sphere's look: energy_ellipsoid, path, line_scale, levels; a world view's line_scale and tip_names.
void read_sphere_options(TableReader& r, ViewConfig& v) {
  for (std::string_view key : {"energy_ellipsoid", "path", "levels"})
    if (r.has(key) && v.kind != ViewKind::momentum_sphere) r.error(key, "only a momentum_sphere view takes " + std::string(key));
  if (r.has("line_scale") && v.kind != ViewKind::momentum_sphere && v.kind != ViewKind::world)
    r.error("line_scale", "only a momentum_sphere or world view takes line_scale");
  if (r.has("tip_names") && v.kind != ViewKind::world) r.error("tip_names", "only a world view takes tip_names");
  v.line_scale = r.number("line_scale", Range::closed(0.25, 4)).value_or(1);
  v.tip_names = r.boolean("tip_names").value_or(true);
  if (r.has("zoom") && v.kind != ViewKind::momentum_sphere) r.error("zoom", "only a momentum_sphere view has a zoom");
  v.zoom = r.number("zoom", Range::closed(1, 1.5)).value_or(1);
  if (r.has("ellipsoid_opacity") && v.kind != ViewKind::momentum_sphere)
    r.error("ellipsoid_opacity", "only a momentum_sphere view draws an energy ellipsoid");
  v.ellipsoid_opacity = r.number("ellipsoid_opacity", Range::closed(0.05, 1));
  if (r.has("level_arrows") && v.kind != ViewKind::momentum_sphere)
    r.error("level_arrows", "only a momentum_sphere view draws level curves");
  v.level_arrows = r.boolean("level_arrows").value_or(true);
  read_world_look(r, v);
  if (v.kind != ViewKind::momentum_sphere) return;
  v.energy_ellipsoid = r.boolean("energy_ellipsoid").value_or(true);
  if (const auto path = r.string("path")) {
    if (*path != "polhode" && *path != "trail" && *path != "trail_on_polhode")
      r.error("path", "expected \"polhode\", \"trail\" or \"trail_on_polhode\", found " + quote_token(*path));
    v.path_trail = *path == "trail" || *path == "trail_on_polhode";
    v.path_faint_polhode = *path == "trail_on_polhode";
  }
  v.levels = static_cast<int>(r.integer("levels", 2, 40).value_or(10));
}

}  // namespace tumble::scene::detail
