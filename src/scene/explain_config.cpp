// [[views]], [[captions]], [title], [[slow_motion]]: explanatory-video settings.
#include <algorithm>

#include "core/observables.hpp"
#include "scene/events.hpp"
#include "scene/frame_clock.hpp"
#include "scene/internal.hpp"

namespace tumble::scene {

const std::vector<std::string>& plot_series_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const Observable& o : observables())
      if (o.use & kPlotSeries) v.insert(v.end(), o.columns.begin(), o.columns.begin() + static_cast<long>(o.size));
    return v;
  }();
  return names;
}

namespace {

// "w1, w2, …, axis3_L": the names a plot takes, for errors.
std::string series_list() {
  std::string out;
  for (const std::string& n : plot_series_names()) out += (out.empty() ? "" : ", ") + n;
  return out;
}

}  // namespace

const char* view_kind_name(ViewKind k) {
  switch (k) {
    case ViewKind::world: return "world";
    case ViewKind::body_frame: return "body_frame";
    case ViewKind::momentum_sphere: return "momentum_sphere";
    case ViewKind::plot: return "plot";
    case ViewKind::poinsot: return "poinsot";
  }
  return "?";
}

namespace detail {

namespace {

std::string indexed(std::string_view key, std::size_t i) { return std::string(key) + "[" + std::to_string(i) + "]"; }

void read_viewport(TableReader& r, ViewConfig& v) {
  const toml::node* n = r.node("viewport");
  if (!n) return;
  const toml::array* a = n->as_array();
  if (!a || a->size() != 4) {
    r.error("viewport", "expected [x, y, width, height] as fractions of the frame from its top-left corner, found " +
                            describe(*n));
    return;
  }
  std::array<double, 4> f{};
  for (std::size_t i = 0; i < 4; ++i) {
    auto x = read_number(*a->get(i), r.key_path("viewport") + "[" + std::to_string(i) + "]", Range::closed(0, 1),
                         r.diag());
    if (!x) return;
    f[i] = *x;
  }
  if (f[2] <= 0 || f[3] <= 0 || f[0] + f[2] > 1 + 1e-9 || f[1] + f[3] > 1 + 1e-9) {
    r.error("viewport", "expected width, height > 0 with x + width <= 1 and y + height <= 1");
    return;
  }
  v.viewport = f;
}

void check_body(TableReader& r, const LoadContext& ctx, const std::string& name) {
  const std::vector<std::string_view> names(ctx.body_names.begin(), ctx.body_names.end());
  if (std::find(names.begin(), names.end(), name) != names.end()) return;
  std::string msg = "expected the name of a body, found " + quote_token(name);
  const std::string hint = closest(name, names);
  if (!hint.empty()) msg += "; did you mean \"" + hint + "\"?";
  r.error("body", msg);
}

void read_world_camera(TableReader& c, ViewConfig& v) {
  auto triple = [&](std::string_view key) -> std::optional<std::array<double, 3>> {
    const auto x = c.vec3(key);
    if (!x) return std::nullopt;
    return std::array<double, 3>{x->x(), x->y(), x->z()};
  };
  v.camera.position = triple("position");
  v.camera.target = triple("target");
  v.camera.up = triple("up");
  v.camera.fov_y_deg = c.number("fov_y", Range::closed(1, 170));
  if (!c.has("position")) c.error("position", "missing; a world view's camera needs position = [x, y, z] (m, world)");
  const auto p = v.camera.position.value_or(std::array<double, 3>{});
  const auto t = v.camera.target.value_or(std::array<double, 3>{});
  if (v.camera.position && p == t) c.error("target", "expected a point other than the camera's position");
  if (v.camera.up && *v.camera.up == std::array<double, 3>{}) c.error("up", "expected a non-zero direction");
}

void read_view_camera(TableReader& r, LoadContext& ctx, ViewConfig& v) {
  auto t = r.subtable("camera");
  if (!t) return;
  if (v.kind == ViewKind::plot) {
    r.error("camera", "a plot view has no camera");
    return;
  }
  const bool across = t->contains("across");
  if (across && v.kind != ViewKind::world && v.kind != ViewKind::body_frame)
    r.error("camera", "only a world or body_frame view looks across L");
  if (v.kind == ViewKind::world && !across) {
    TableReader c(*t, r.key_path("camera"), ctx.diag, {"position", "target", "up", "fov_y"});
    read_world_camera(c, v);
    return;
  }
  TableReader c(*t, r.key_path("camera"), ctx.diag,
                v.kind == ViewKind::world ? std::vector<std::string_view>{"across", "azimuth", "elevation", "roll"}
                                          : std::vector<std::string_view>{"across", "azimuth", "elevation", "distance", "follow", "up"});
  if (across) v.camera.across = read_across(c);
  v.camera.azimuth_deg = c.number("azimuth", Range::closed(-360, 360));
  // A sphere may be seen straight down an axis (its up is then the azimuth's direction); other views keep 1° off.
  const double steepest = v.kind == ViewKind::momentum_sphere ? 90 : 89;
  v.camera.elevation_deg = c.number("elevation", Range::closed(-steepest, steepest));
  v.camera.distance = c.number("distance", Range::closed(1.5, 100));
  v.camera.roll_deg = c.number("roll", Range::closed(-180, 180));
  v.camera.follow = c.boolean("follow");
  if (const auto up = c.vec3("up")) {
    if (v.kind != ViewKind::momentum_sphere && v.kind != ViewKind::body_frame)
      c.error("up", "only a momentum_sphere or body_frame view takes up (a principal direction)");
    else if (across) c.error("up", "a body_frame camera looks across L or from principal axes (up), not both");
    else if (up->norm() < 1e-12) c.error("up", "expected a non-zero direction");
    else v.camera.up = std::array<double, 3>{up->x(), up->y(), up->z()};
  }
}

// Keys only some kinds take: the sphere's (above), y_scale, shade_speeds, energy_levels and y_range (plot).
void read_kind_options(TableReader& r, ViewConfig& v) {
  read_sphere_options(r, v);
  if (const auto scale = r.string("y_scale")) {
    if (v.kind != ViewKind::plot) r.error("y_scale", "only a plot view has a y_scale");
    else if (*scale == "log") v.y_log = true;
    else if (*scale != "linear") r.error("y_scale", "expected \"linear\" or \"log\", found " + quote_token(*scale));
  }
  if (const auto shade = r.boolean("shade_speeds")) {
    if (v.kind != ViewKind::plot) r.error("shade_speeds", "only a plot view shades its speeds");
    else v.shade_speeds = *shade;
  }
  if (const auto lv = r.boolean("energy_levels")) {
    if (v.kind != ViewKind::plot) r.error("energy_levels", "only a plot view draws energy levels");
    else if (std::find(v.series.begin(), v.series.end(), "energy_error") == v.series.end())
      r.error("energy_levels", "the levels are energies: expected series = [\"energy_error\"]");
    else v.energy_levels = *lv;
  }
  if (const toml::node* n = r.node("y_range")) {
    if (v.kind != ViewKind::plot) {
      r.error("y_range", "only a plot view has a y_range");
      return;
    }
    const toml::array* a = n->as_array();
    std::optional<double> lo, hi;
    if (a && a->size() == 2) {
      lo = read_number(*a->get(0), r.key_path("y_range") + "[0]", Range::any(), r.diag());
      hi = read_number(*a->get(1), r.key_path("y_range") + "[1]", Range::any(), r.diag());
    } else {
      r.error("y_range", "expected [low, high] in the series' units, found " + describe(*n));
    }
    if (lo && hi && !(*hi > *lo)) r.error("y_range", "expected low < high, found [" + format_number(*lo) + ", " + format_number(*hi) + "]");
    else if (lo && v.y_log && !(*lo > 0)) r.error("y_range", "a log scale needs low > 0, found " + format_number(*lo));
    else if (lo && hi) v.y_range = std::array<double, 2>{*lo, *hi};
  }
}

void read_views(TableReader& root, LoadContext& ctx, Scene& s) {
  const auto list = root.tables("views");
  for (std::size_t i = 0; i < list.size(); ++i) {
    TableReader r(*list[i], indexed("views", i), ctx.diag,
                  {"kind", "viewport", "body", "series", "title", "camera", "energy_ellipsoid", "y_range", "y_scale", "appear",
                   "key", "path", "line_scale", "levels", "shade_speeds", "tip_names", "turn", "energy_levels",
                   "ellipsoid_from", "ellipsoid_opacity", "level_arrows", "build_up", "trail_axes", "box", "zoom",
                   "dot_scale", "dark_levels", "readout", "until", "paths_of", "path_on_top", "trails", "see_through",
                   "L_width", "omega_width", "trail_width", "separatrix", "close_up", "hide_far_side"});
    ViewConfig v;
    const auto kind = r.string("kind");
    if (!kind) {
      if (!r.has("kind")) r.error("kind", "missing; expected world, body_frame, momentum_sphere, plot or poinsot");
      continue;
    }
    bool known = false;
    for (ViewKind k : {ViewKind::world, ViewKind::body_frame, ViewKind::momentum_sphere, ViewKind::plot,
                       ViewKind::poinsot})
      if (*kind == view_kind_name(k)) v.kind = k, known = true;
    if (!known) r.error("kind", "expected world, body_frame, momentum_sphere, plot or poinsot, found " + quote_token(*kind));
    read_viewport(r, v);
    v.body = r.string("body").value_or("");
    if (!v.body.empty()) check_body(r, ctx, v.body);
    v.title = r.string("title").value_or("");
    if (auto series = r.strings("series")) {
      for (const std::string& name : *series) {
        const auto& all = plot_series_names();
        if (std::find(all.begin(), all.end(), name) == all.end())
          r.error("series", "expected names from " + series_list() + ", found " + quote_token(name));
      }
      v.series = *series;
    }
    if (v.kind == ViewKind::plot && v.series.empty()) v.series = {"w1", "w2", "w3"};
    read_view_camera(r, ctx, v);
    read_kind_options(r, v);
    v.key = r.boolean("key").value_or(true);
    if (v.kind != ViewKind::plot && r.has("series")) r.error("series", "only a plot view has series");
    const std::size_t body = v.body.empty() || !s.find_body(v.body) ? 0 : static_cast<std::size_t>(s.find_body(v.body) - s.bodies.data());
    // A view that would appear past the run's end (a shorter --duration) never does.
    v.appear = read_time(r, "appear", s, body, &v.appear_text).value_or(r.has("appear") ? 1e300 : 0);
    if (r.has("ellipsoid_from") && v.kind != ViewKind::momentum_sphere)
      r.error("ellipsoid_from", "only a momentum_sphere view draws an energy ellipsoid");
    v.ellipsoid_from = read_time(r, "ellipsoid_from", s, body).value_or(r.has("ellipsoid_from") ? 1e300 : 0);
    read_sphere_marks(r, v);
    read_sphere_paths(r, ctx, v);
    read_turn(r, ctx, s, body, v);
    read_build_up(r, s, body, v);
    read_view_readout(r, s, body, v);
    s.render.explain.views.push_back(std::move(v));
  }
  // A comparison lays out its own grid of cells; plots of its runs, or a momentum sphere with each run's Π, may go beside it.
  const bool only_plots = std::all_of(s.render.explain.views.begin(), s.render.explain.views.end(), [](const ViewConfig& v) {
    return (v.kind == ViewKind::plot || v.kind == ViewKind::momentum_sphere) && v.viewport;
  });
  if (!s.render.compare_methods.empty() && !only_plots)
    root.error("views", "with [compare], [[views]] may only add plots or momentum spheres, each with its viewport; the "
                        "comparison lays out its own grid of cells in the rest of the frame");
}

// The body named by `body` (checked), else the first.
std::size_t read_body_index(TableReader& r, const LoadContext& ctx, const Scene& s) {
  const auto name = r.string("body");
  if (!name) return 0;
  check_body(r, ctx, *name);
  const Body* b = s.find_body(*name);
  return b ? static_cast<std::size_t>(b - s.bodies.data()) : 0;
}

}  // namespace

// `key` as simulated seconds or an event of body `body` (scene/events.hpp),
// clamped to [0, duration]; `written` gets the text as the file has it. A
// time in seconds past the run's end (a shorter --duration, to preview the
// start) is none, with a warning: what it places is left out (an end, the run's end).
std::optional<double> read_time(TableReader& r, std::string_view key, const Scene& s, std::size_t body,
                                std::string* written) {
  const toml::node* n = r.node(key);
  if (!n) return std::nullopt;
  const double duration = s.simulation.duration;
  if (n->is_number()) {
    auto v = read_number(*n, r.key_path(key), Range::non_negative(), r.diag());
    if (v && written) *written = format_number(*v);
    if (v && *v > duration) {
      r.diag().warning(n->source(), r.key_path(key), format_number(*v) + " s is past the run's end (" +
                                                        format_number(duration) + " s): left out");
      return std::nullopt;
    }
    return v;
  }
  const auto* str = n->as_string();
  const auto e = str ? parse_event_time(str->get()) : std::nullopt;
  if (!e) {
    r.error(key, std::string("expected ") + kEventTimeForms + ", found " + describe(*n));
    return std::nullopt;
  }
  if (written) *written = str->get();
  if (!r.diag().ok() || body >= s.bodies.size()) return std::nullopt;  // the bodies are not all there
  const std::vector<double> flips = body_flip_times(s, body);
  if (static_cast<std::size_t>(e->flip) > flips.size()) {
    std::string at;
    for (double f : flips) at += (at.empty() ? " at " : ", ") + format_number(f) + " s";
    r.error(key, "body '" + s.bodies[body].name + "' flips " + std::to_string(flips.size()) + " time(s) in " +
                     format_number(duration) + " s" + at + "; there is no flip " + std::to_string(e->flip));
    return std::nullopt;
  }
  return std::clamp(flips[static_cast<std::size_t>(e->flip - 1)] + e->offset, 0.0, duration);
}

namespace {

// A caption's `after` and `seconds` (video s): shown in turn within a hold; `seconds` replaces `end`.
void read_caption_video_times(TableReader& r, Caption& c) {
  c.after = r.number("after", Range::closed(0, 3600)).value_or(0);
  c.seconds = r.number("seconds", Range::closed(0.1, 3600)).value_or(0);
  if (r.has("seconds") && r.has("end"))
    r.error("seconds", "a caption ends at `end` (simulated s) or after `seconds` (video s), not both");
}

void read_captions(TableReader& root, LoadContext& ctx, Scene& s) {
  const auto list = root.tables("captions");
  for (std::size_t i = 0; i < list.size(); ++i) {
    TableReader r(*list[i], indexed("captions", i), ctx.diag, {"start", "end", "text", "body", "position", "after", "seconds"});
    Caption c;
    c.body = read_body_index(r, ctx, s);
    const auto start = read_time(r, "start", s, c.body, &c.start_text);
    if (!start && r.has("start")) continue;  // said why: past the run's end, or an error
    c.start = start.value_or(0);
    read_caption_video_times(r, c);
    c.end = c.seconds > 0 ? c.start : read_time(r, "end", s, c.body, &c.end_text).value_or(s.simulation.duration);
    if (c.seconds <= 0 && c.end <= c.start && ctx.diag.ok())
      r.error("end", "expected end > start (simulated s); found start " + format_number(c.start) + " s, end " +
                         format_number(c.end) + " s");
    auto text = r.string("text");
    if (!text) {
      if (!r.has("text")) r.error("text", "missing; a caption needs text = \"...\"");
    } else {
      c.text = *text;
    }
    if (auto pos = r.string("position")) {
      if (*pos == "top") c.position = CaptionPosition::top;
      else if (*pos != "bottom") r.error("position", "expected \"bottom\" or \"top\", found " + quote_token(*pos));
    }
    // The captions share one strip across the frame: they agree where it is.
    const auto& before = s.render.explain.captions;
    if (!before.empty() && before.front().position != c.position)
      r.error("position", "every caption shares one strip: captions[0] puts it at the " +
                              std::string(before.front().position == CaptionPosition::top ? "top" : "bottom") +
                              "; give each caption the same position");
    s.render.explain.captions.push_back(std::move(c));
  }
}

void read_slow_motion(TableReader& root, LoadContext& ctx, Scene& s) {
  const auto list = root.tables("slow_motion");
  auto& out = s.render.explain.slow_motion;
  for (std::size_t i = 0; i < list.size(); ++i) {
    TableReader r(*list[i], indexed("slow_motion", i), ctx.diag, {"start", "end", "time_scale", "body"});
    SlowMotion m;
    const std::size_t body = read_body_index(r, ctx, s);
    const auto a = read_time(r, "start", s, body);
    const auto b = read_time(r, "end", s, body);
    if (!a && !r.has("start")) r.error("start", "missing (simulated s)");
    if (!b && !r.has("end")) r.error("end", "missing (simulated s)");
    if (!a || !b) continue;
    m.start = *a, m.end = *b;
    m.time_scale = r.number("time_scale", Range::closed(1e-4, 1e4)).value_or(m.time_scale);
    if (m.end <= m.start) {
      r.error("end", "expected end > start");
      continue;
    }
    for (const SlowMotion& o : out)
      if (m.start < o.end && o.start < m.end) r.error("start", "overlaps an earlier slow_motion segment");
    out.push_back(m);
  }
  std::sort(out.begin(), out.end(), [](const SlowMotion& x, const SlowMotion& y) { return x.start < y.start; });
}

void read_holds(TableReader& root, LoadContext& ctx, Scene& s) {
  const auto list = root.tables("holds");
  auto& out = s.render.explain.holds;
  for (std::size_t i = 0; i < list.size(); ++i) {
    TableReader r(*list[i], indexed("holds", i), ctx.diag, {"at", "hold", "body", "label"});
    Hold h;
    const std::size_t body = read_body_index(r, ctx, s);
    const auto at = read_time(r, "at", s, body, &h.at_text);
    if (!at && !r.has("at")) r.error("at", std::string("missing; expected ") + kEventTimeForms);
    h.hold = r.number("hold", Range::closed(0.1, 60)).value_or(h.hold);
    h.label = r.string("label").value_or("");
    if (!at) continue;
    h.at = *at;
    out.push_back(h);
  }
  std::stable_sort(out.begin(), out.end(), [](const Hold& x, const Hold& y) { return x.at < y.at; });
}

void read_title(TableReader& root, LoadContext& ctx, Scene& s) {
  auto t = root.subtable("title");
  if (!t) return;
  TableReader r(*t, "title", ctx.diag, {"text", "subtitle", "hold", "duration"});
  TitleCard& c = s.render.explain.title;
  c.text = r.string("text").value_or("");
  c.subtitle = r.string("subtitle").value_or("");
  c.hold = r.number("hold", Range::closed(0, 60)).value_or(2.5);
  if (c.text.empty()) r.error("text", "missing; a title card needs text = \"...\"");
  if (r.has("duration"))
    r.error("duration", "renamed to hold: the video s the title card is shown while the animation waits");
}

}  // namespace

void read_explain_config(TableReader& root, LoadContext& ctx, Scene& s) {
  read_views(root, ctx, s);
  read_captions(root, ctx, s);
  read_slow_motion(root, ctx, s);
  read_holds(root, ctx, s);
  read_title(root, ctx, s);
  auto& e = s.render.explain;
  if (!e.views.empty() && s.render.compare_methods.empty()) {
    // The axis legend belongs to the classic single view; [[views]] have keys.
    const toml::table* draw = root.subtable("draw");
    const toml::node* legend = draw ? draw->get("legend") : nullptr;
    if (legend && legend->value_or(false))
      ctx.diag.error(legend->source(), "draw.legend",
                     "a scene with [[views]] shows each view's key instead (draw.key); remove legend = true");
    s.render.draw.legend = false;
  }
  if (root.diag().ok()) check_pacing(root, ctx, s);
  if ((!e.slow_motion.empty() || e.title.hold > 0 || !e.holds.empty()) && root.diag().ok() &&
      frame_clock(s, s.render.output.fps).count() > static_cast<long>(kMaxFrames))
    root.error(e.slow_motion.empty() ? "title" : "slow_motion",
               "the slowed video exceeds the frame cap of " + std::to_string(static_cast<long>(kMaxFrames)));
}

}  // namespace detail
}  // namespace tumble::scene
