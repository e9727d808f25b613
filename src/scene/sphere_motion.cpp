// A momentum_sphere's timed camera and figure: its `turn` (the fixed camera
// turning at an anchored time) and its `build_up` (the figure drawn in steps).
#include <algorithm>
#include <string>

#include "scene/internal.hpp"

namespace tumble::scene::detail {

// A momentum_sphere's `turn = { at, azimuth, elevation, seconds }`: its fixed camera turning at `at`.
void read_turn(TableReader& r, LoadContext& ctx, const Scene& s, std::size_t body, ViewConfig& v) {
  const toml::table* t = r.subtable("turn");
  if (!t) return;
  if (v.kind != ViewKind::momentum_sphere) return r.error("turn", "only a momentum_sphere view turns its camera");
  if (v.camera.follow.value_or(false)) return r.error("turn", "a camera that follows Π does not turn; set follow = false");
  TableReader c(*t, r.key_path("turn"), ctx.diag, {"at", "azimuth", "elevation", "seconds"});
  ViewConfig::Turn turn;
  const auto at = read_time(c, "at", s, body);
  const auto az = c.number("azimuth", Range::closed(-360, 360)), el = c.number("elevation", Range::closed(-90, 90));
  const auto seconds = c.number("seconds", Range::closed(0.1, 600));
  for (const char* key : {"at", "azimuth", "elevation", "seconds"})
    if (!c.has(key)) c.error(key, "missing; a turn needs at, azimuth, elevation and seconds (video s)");
  if (!at || !az || !el || !seconds) return;
  turn.at = *at, turn.azimuth_deg = *az, turn.elevation_deg = *el, turn.seconds = *seconds;
  v.turn = turn;
}

// A momentum_sphere's `build_up = { at, seconds = [sphere, ellipsoid, curves, separatrix] }` (video s).
void read_build_up(TableReader& r, const Scene& s, std::size_t body, ViewConfig& v) {
  const toml::table* t = r.subtable("build_up");
  if (!t) return;
  if (v.kind != ViewKind::momentum_sphere) return r.error("build_up", "only a momentum_sphere view builds up its figure");
  TableReader c(*t, r.key_path("build_up"), r.diag(), {"at", "seconds"});
  const char* steps = "4 video s, one a step: [sphere, ellipsoid, curves, separatrix]";
  const auto at = read_time(c, "at", s, body);
  if (!c.has("at")) c.error("at", std::string("missing; a build-up needs at (simulated s) and seconds = ") + steps);
  const toml::array* a = c.node("seconds") ? c.node("seconds")->as_array() : nullptr;
  if (!a || a->size() != 4)
    return c.error("seconds", std::string(c.has("seconds") ? "expected " : "missing; expected ") + steps +
                                  (c.has("seconds") ? ", found " + describe(*c.node("seconds")) : ""));
  ViewConfig::BuildUp b;
  bool ok = at.has_value();
  for (std::size_t i = 0; i < 4; ++i) {
    const auto x = read_number(*a->get(i), c.key_path("seconds") + "[" + std::to_string(i) + "]", Range::closed(0.1, 600), c.diag());
    ok = ok && x;
    if (x) b.seconds[i] = *x;
  }
  if (!ok) return;
  b.at = *at;
  v.build_up = b;
}

}  // namespace tumble::scene::detail
