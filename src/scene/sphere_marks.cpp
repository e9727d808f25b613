// A momentum_sphere's marks sized for a hall: Π's dot larger (dot_scale) and
// the other levels dark (dark_levels), so the figure reads from the back.
#include "scene/internal.hpp"

namespace tumble::scene::detail {

void read_sphere_marks(TableReader& r, ViewConfig& v) {
  for (const char* key : {"dot_scale", "dark_levels"})
    if (r.has(key) && v.kind != ViewKind::momentum_sphere)
      r.error(key, std::string("only a momentum_sphere view takes ") + key);
  v.dot_scale = r.number("dot_scale", Range::closed(0.5, 5)).value_or(1);
  v.dark_levels = r.boolean("dark_levels").value_or(false);
}

}  // namespace tumble::scene::detail
