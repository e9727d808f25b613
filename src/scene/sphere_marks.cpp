// A momentum_sphere's marks sized for a hall: Π's dot larger (dot_scale),
// the other levels dark (dark_levels), Π's trail over the separatrix it runs
// beside (path_on_top), so the figure reads from the back; nothing drawn
// behind the ball (hide_far_side: faint, it reads as on the front); a poinsot
// view's ellipsoid with its separatrix (separatrix);
// several bodies' Π on the one sphere (paths_of), each on its own |L|.
#include <algorithm>

#include "scene/internal.hpp"

namespace tumble::scene::detail {

void read_sphere_marks(TableReader& r, ViewConfig& v) {
  for (const char* key : {"dot_scale", "dark_levels", "path_on_top", "hide_far_side"})
    if (r.has(key) && v.kind != ViewKind::momentum_sphere)
      r.error(key, std::string("only a momentum_sphere view takes ") + key);
  v.dot_scale = r.number("dot_scale", Range::closed(0.5, 5)).value_or(1);
  v.dark_levels = r.boolean("dark_levels").value_or(false);
  v.path_on_top = r.boolean("path_on_top").value_or(false);
  v.hide_far_side = r.boolean("hide_far_side").value_or(false);
  if (r.has("separatrix") && v.kind != ViewKind::poinsot)
    r.error("separatrix", "only a poinsot view takes separatrix (a momentum_sphere always draws it)");
  v.separatrix = r.boolean("separatrix").value_or(false);
  if (r.has("close_up") && v.kind != ViewKind::poinsot) r.error("close_up", "only a poinsot view takes close_up");
  v.close_up = r.boolean("close_up").value_or(false);
}

void read_sphere_paths(TableReader& r, const LoadContext& ctx, ViewConfig& v) {
  const auto names = r.strings("paths_of");
  if (!names) return;
  if (v.kind != ViewKind::momentum_sphere) r.error("paths_of", "only a momentum_sphere view takes paths_of");
  const std::vector<std::string_view> known(ctx.body_names.begin(), ctx.body_names.end());
  for (const std::string& name : *names) {
    if (std::find(known.begin(), known.end(), name) != known.end()) continue;
    std::string msg = "expected names of bodies, found " + quote_token(name);
    const std::string hint = closest(name, known);
    if (!hint.empty()) msg += "; did you mean \"" + hint + "\"?";
    r.error("paths_of", msg);
    return;
  }
  if (names->empty()) r.error("paths_of", "expected at least one body's name");
  else if (v.kind == ViewKind::momentum_sphere) v.paths_of = *names;
}

}  // namespace tumble::scene::detail
