// Render sections: parsed and validated with the scene, used by `tumble render`.
#include <algorithm>

#include "base/format.hpp"
#include "core/propagator.hpp"
#include "scene/internal.hpp"
#include "viz/camera_up.hpp"

namespace tumble::scene::detail {

int read_across(TableReader& r) {
  const auto a = r.string("across");
  if (!a) return 0;
  if (*a == "L") return 1;
  if (*a == "-L") return -1;
  r.error("across", "expected \"L\" (L up in the picture) or \"-L\" (L down), found " + quote_token(*a));
  return 0;
}

namespace {

void read_output(TableReader& r, Scene& s) {
  OutputConfig& o = s.render.output;
  o.fps = s.simulation.fps;
  o.width = static_cast<int>(r.integer("width", kMinFramePx, kMaxFramePx).value_or(o.width));
  o.height = static_cast<int>(r.integer("height", kMinFramePx, kMaxFramePx).value_or(o.height));
  Range fps = Range::closed(1e-3, 1000);
  o.fps = r.number("fps", fps).value_or(o.fps);
  const std::optional<long long> m = r.integer("msaa", 0, 4);
  if (m) {
    if (valid_msaa_samples(*m)) o.msaa = static_cast<int>(*m);
    else r.error("msaa", "expected 0, 2 or 4, found " + std::to_string(*m));
  }
  if (auto a = r.string("aa")) {
    if (const std::optional<Antialias> aa = parse_antialias(*a)) o.aa = *aa;
    else r.error("aa", "expected " + antialias_choices('"') + ", found " + quote_token(*a));
    if (o.aa == Antialias::msaa && m && *m == 0) r.error("msaa", "aa = \"msaa\" needs msaa = 2 or 4, found 0");
  } else if (m) {
    // Scenes written before `aa` existed: msaa = N meant N samples, 0 none.
    o.aa = o.msaa > 0 ? Antialias::msaa : Antialias::none;
  }
  o.background = r.vec3("background", Range::closed(0, 1)).value_or(o.background);
  s.render.explain.time_scale = r.number("time_scale", Range::closed(1e-4, 1e4)).value_or(1.0);
  if (auto v = r.string("video")) {
    if (const std::optional<VideoFormat> f = parse_video_format(*v)) o.video = *f;
    else r.error("video", "expected " + video_format_choices('"') + ", found " + quote_token(*v));
  }
  if (o.fps * s.simulation.duration / s.render.explain.time_scale > kMaxFrames)
    r.error("fps", "duration × fps exceeds the frame cap of " + std::to_string(static_cast<long>(kMaxFrames)));
}

void read_camera(TableReader& r, const LoadContext& ctx, Scene& s) {
  CameraConfig& c = s.render.camera;
  if (r.has("across")) {
    c.across = read_across(r);
    if (r.has("position")) r.error("across", "a camera across L finds its own position; remove 'position'");
    if (r.has("auto")) r.error("across", "a camera across L is placed by L; remove 'auto'");
    c.azimuth_deg = r.number("azimuth", Range::closed(-360, 360)).value_or(c.azimuth_deg);
    c.elevation_deg = r.number("elevation", Range::closed(-80, 80)).value_or(c.elevation_deg);
    c.roll_deg = r.number("roll", Range::closed(-180, 180)).value_or(c.roll_deg);
  } else if (r.has("azimuth") || r.has("elevation") || r.has("roll")) {
    const char* key = r.has("azimuth") ? "azimuth" : r.has("elevation") ? "elevation" : "roll";
    r.error(key, "only a camera across L (across = \"L\") takes azimuth, elevation and roll");
  }
  const bool has_position = r.has("position");
  c.automatic = r.boolean("auto").value_or(!has_position);
  if (c.automatic && has_position && r.has("auto"))
    r.error("auto", "auto = true frames the bodies itself; remove 'position' or set auto = false");
  c.position = r.vec3("position").value_or(c.position);
  c.target = r.vec3("target").value_or(c.target);
  c.up = r.vec3("up").value_or(c.up);
  if (c.up.norm() < 1e-12) r.error("up", "expected a non-zero vector");
  c.fov_y_deg = r.number("fov_y", {1, 170, false, "an angle in [1, 170] degrees"}).value_or(c.fov_y_deg);
  if (!c.automatic && (c.position - c.target).norm() < 1e-12)
    r.error("target", "camera position and target coincide");
  else if (const Eigen::Vector3d up = viz::usable_up(c.up, c.target - c.position); !c.automatic && c.up.norm() >= 1e-12 && up != c.up) {
    r.diag().warning(r.node("up") ? r.node("up")->source() : r.where(), r.key_path("up"), "parallel to the view direction (position to target), which leaves the image's up undefined; "
                    "using up = [" + format_number(up.x()) + ", " + format_number(up.y()) + ", " + format_number(up.z()) + "] (+y, or +x when looking along y)");
    c.up = up;
  }
  if (auto f = r.string("follow")) {
    const std::vector<std::string_view> names(ctx.body_names.begin(), ctx.body_names.end());
    if (std::find(names.begin(), names.end(), *f) == names.end()) {
      std::string msg = "expected the name of a body, found " + quote_token(*f);
      const std::string hint = closest(*f, names);
      if (!hint.empty()) msg += "; did you mean \"" + hint + "\"?";
      r.error("follow", msg);
    }
    c.follow = *f;
  }
}

// `flips`: true marks the first body's flips on screen, a body's name that body's.
void read_flip_marks(TableReader& r, const LoadContext& ctx, Scene& s) {
  const toml::node* n = r.node("flips");
  if (!n) return;
  if (const auto* b = n->as_boolean()) {
    if (b->get()) s.render.explain.flip_marks = 0;
    return;
  }
  const auto name = r.string("flips");
  if (!name) return;  // the reader said what it expected
  const auto at = std::find(ctx.body_names.begin(), ctx.body_names.end(), *name);
  if (at == ctx.body_names.end()) return r.error("flips", "expected true, false or the name of a body, found " + quote_token(*name));
  s.render.explain.flip_marks = static_cast<std::size_t>(at - ctx.body_names.begin());
}

void read_draw(TableReader& r, const LoadContext& ctx, Scene& s) {
  DrawConfig& d = s.render.draw;
  if (r.has("box")) d.box = r.boolean("box");
  d.surface = r.boolean("surface").value_or(d.surface);
  d.axes = r.boolean("axes").value_or(d.axes);
  d.particles = r.boolean("particles").value_or(d.particles);
  d.angular_momentum = r.boolean("L").value_or(d.angular_momentum);
  d.omega = r.boolean("omega").value_or(d.omega);
  d.trail_seconds = r.number("trails", Range::closed(0, 1e4)).value_or(d.trail_seconds);
  if (const auto axes = r.strings("trail_axes")) {
    d.trail_axes = {false, false, false};
    for (const std::string& a : *axes) {
      if (a == "e1" || a == "e2" || a == "e3") d.trail_axes[static_cast<std::size_t>(a[1] - '1')] = true;
      else r.error("trail_axes", "expected items from \"e1\", \"e2\", \"e3\", found " + quote_token(a));
    }
  }
  d.grid = r.boolean("grid").value_or(d.grid);
  d.arrow_width = r.number("arrow_width", Range::closed(0.25, 4)).value_or(d.arrow_width);
  d.arrow_length = r.number("arrow_length", Range::closed(0.25, 4)).value_or(d.arrow_length);
  d.text_scale = r.number("text_scale", Range::closed(0.5, 1.5)).value_or(d.text_scale);
  d.tip_names_further = r.boolean("tip_names_further").value_or(d.tip_names_further);
  if (const auto items = read_overlay_items(r, "overlay")) {
    d.overlay_items = *items;  // a list of the overlay's items: only those are shown
    d.overlay = d.overlay_items.any();
  } else {
    d.overlay = r.boolean("overlay").value_or(d.overlay);
  }
  s.render.explain.labels = r.boolean("labels").value_or(false);
  s.render.explain.key = r.boolean("key").value_or(true);
  d.legend = r.boolean("legend").value_or(d.legend);
  read_flip_marks(r, ctx, s);
  s.render.explain.flip_badge_seconds = r.number("flip_badge", Range::closed(0.5, 10)).value_or(s.render.explain.flip_badge_seconds);
}

// Which of the compared methods get a cell: fewer, larger pictures; the
// rest still run, and still show in the plots under the cells.
void read_compare_cells(TableReader& r, Scene& s) {
  if (!r.has("cells")) return;
  auto names = r.strings("cells");
  if (!names) return;
  if (names->empty()) r.error("cells", "expected at least one of the compared methods");
  for (const std::string& n : *names) {
    const auto m = parse_method(n);
    const auto& all = s.render.compare_methods;
    if (!m || std::find(all.begin(), all.end(), *m) == all.end()) {
      r.error("cells", "expected one of the methods listed in [compare] methods, found " + quote_token(n));
      continue;
    }
    if (std::find(s.render.compare_cells.begin(), s.render.compare_cells.end(), *m) != s.render.compare_cells.end()) {
      r.error("cells", "method \"" + n + "\" is listed twice");
      continue;
    }
    s.render.compare_cells.push_back(*m);
  }
}

// Each method's own step: one table, method = dt (s). Only a compared method
// that steps at a fixed dt may have one (an adaptive pair takes rtol/atol).
void read_compare_steps(TableReader& r, Scene& s) {
  if (!r.has("steps")) return;
  const toml::table* t = r.subtable("steps");
  if (!t) return;
  std::vector<std::string_view> names;  // the compared methods: any other key is refused, with a did-you-mean
  for (Method m : s.render.compare_methods) names.push_back(method_name(m));
  TableReader steps(*t, r.key_path("steps"), r.diag(), names);
  for (auto&& [k, v] : *t) {
    const std::string name(k.str());
    const auto m = parse_method(name);
    if (!m || std::find(names.begin(), names.end(), name) == names.end()) continue;  // reported above
    if (method_info(*m).adaptive) {
      steps.error(name, "method \"" + name + "\" is adaptive: it takes rtol/atol in [simulation], not a dt");
      continue;
    }
    const auto dt = steps.number(name, Range::positive());
    if (!dt) continue;
    if (s.simulation.duration / *dt > kMaxRunSteps) {
      steps.error(name, "expected at most " + format_number(kMaxRunSteps) + " steps (duration / dt, the cap), found " +
                            format_number(s.simulation.duration / *dt, 3));
      continue;
    }
    s.render.compare_steps.emplace_back(*m, *dt);
  }
}

// Where the cells stand: one name of kCompareArranges.
void read_compare_arrange(TableReader& r, Scene& s) {
  const auto a = r.string("arrange");
  if (!a) return;
  std::string names;
  for (const auto& [value, name] : kCompareArranges) {
    if (*a == name) return void(s.render.compare_arrange = value);
    names += std::string(names.empty() ? "" : " or ") + '"' + name + '"';
  }
  r.error("arrange", "expected " + names + ", found " + quote_token(*a));
}

void read_compare(TableReader& r, Scene& s) {
  auto names = r.strings("methods");
  if (!names) {
    if (!r.has("methods")) r.error("methods", "missing; [compare] needs methods = [\"euler\", \"rk4\", ...]");
    return;
  }
  if (names->empty() || names->size() > 16) {
    r.error("methods", "expected 1 to 16 method names, found " + std::to_string(names->size()));
    return;
  }
  for (std::size_t i = 0; i < names->size(); ++i) {
    const std::string& n = (*names)[i];
    auto m = parse_method(n);
    if (!m) {
      r.error("methods", "entry " + std::to_string(i) + ": expected one of " + method_list() + ", found " + quote_token(n));
      continue;
    }
    if (std::find(s.render.compare_methods.begin(), s.render.compare_methods.end(), *m) !=
        s.render.compare_methods.end()) {
      r.error("methods", "method \"" + n + "\" is listed twice");
      continue;
    }
    s.render.compare_methods.push_back(*m);
  }
  read_compare_cells(r, s);
  read_compare_steps(r, s);
  read_compare_arrange(r, s);
}

}  // namespace

void read_output_config(TableReader& root, LoadContext& ctx, Scene& scene) {
  scene.render.output.fps = scene.simulation.fps;
  if (auto t = root.subtable("output")) {
    TableReader r(*t, "output", ctx.diag, {"width", "height", "fps", "aa", "msaa", "background", "video", "time_scale"});
    read_output(r, scene);
  }
}

void read_render_config(TableReader& root, LoadContext& ctx, Scene& scene) {
  read_output_config(root, ctx, scene);
  if (auto t = root.subtable("camera")) {
    TableReader r(*t, "camera", ctx.diag, {"position", "target", "up", "fov_y", "auto", "follow", "across", "azimuth", "elevation", "roll"});
    read_camera(r, ctx, scene);
  }
  if (auto t = root.subtable("draw")) {
    TableReader r(*t, "draw", ctx.diag,
                  {"box", "surface", "axes", "particles", "L", "omega", "trails", "trail_axes", "grid", "overlay", "legend", "labels", "key",
                   "flips", "arrow_width", "arrow_length", "text_scale",
                   "tip_names_further", "flip_badge"});
    read_draw(r, ctx, scene);
  }
  if (auto t = root.subtable("compare")) {
    TableReader r(*t, "compare", ctx.diag, {"methods", "cells", "steps", "arrange"});
    read_compare(r, scene);
  }
}

}  // namespace tumble::scene::detail
