// Top level of the loader: syntax, [simulation], [forces], then bodies and render.
#include "scene/scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "base/input_file.hpp"

#include "scene/internal.hpp"
#include "scene/toml_limits.hpp"

namespace tumble::scene {

namespace {

using detail::Range;
using detail::TableReader;

void read_simulation(TableReader& root, detail::LoadContext& ctx, Scene& s) {
  SimulationConfig& sim = s.simulation;
  const toml::table* t = root.subtable("simulation");
  if (!t) return;
  TableReader r(*t, "simulation", ctx.diag, {"method", "dt", "duration", "fps", "rtol", "atol", "tolerance"});
  if (auto m = r.string("method")) {
    if (*m == "auto") sim.automatic = true;
    else if (auto pm = parse_method(*m)) sim.step.method = *pm;
    else {
      std::vector<std::string_view> names{"auto"};
      for (Method k : kAllMethods) names.push_back(method_name(k));
      std::string msg = "expected \"auto\" or one of " + method_list() + ", found " + quote_token(*m);
      const std::string hint = detail::closest(*m, names);
      if (!hint.empty()) msg += "; did you mean \"" + hint + "\"?";
      r.error("method", msg);
    }
  }
  const std::optional<double> dt = r.number("dt", Range::positive());
  sim.step.dt = dt.value_or(sim.step.dt);
  sim.tolerance = r.number("tolerance", Range::closed(1e-12, 1));
  if (sim.tolerance && !sim.automatic)
    r.error("tolerance", "expected method = \"auto\" with a tolerance (it picks the method and dt that meet it), "
                         "found method = \"" + std::string(method_name(sim.step.method)) + "\"; remove one of them");
  else if (sim.tolerance && dt)
    r.error("dt", "expected no dt with method = \"auto\" and a tolerance: auto picks dt itself; remove dt or the tolerance");
  sim.duration = r.number("duration", Range::positive()).value_or(sim.duration);
  sim.fps = r.number("fps", Range::closed(1e-3, 1000)).value_or(sim.fps);
  sim.step.rtol = r.number("rtol", {0, 1, true, "a tolerance in (0, 1]"}).value_or(sim.step.rtol);
  sim.step.atol = r.number("atol", {0, 1e300, true, "a tolerance > 0"}).value_or(sim.step.atol);
  if (sim.step.dt > sim.duration)
    r.error("dt", "expected dt <= duration (" + format_number(sim.duration) + " s), found " +
                      format_number(sim.step.dt));
  else if (sim.duration / sim.step.dt > kMaxRunSteps)
    r.error("dt", "expected at most " + format_number(kMaxRunSteps) + " steps (duration / dt, the cap), found " +
                      format_number(sim.duration / sim.step.dt) + "; raise dt");
  if (sim.duration * sim.fps > kMaxFrames)
    r.error("fps", "duration × fps = " + format_number(sim.duration * sim.fps) + " exceeds the frame cap of " +
                       std::to_string(static_cast<long>(kMaxFrames)));
}

void read_forces(TableReader& root, detail::LoadContext& ctx, Scene& s) {
  const toml::table* t = root.subtable("forces");
  if (!t) return;
  TableReader r(*t, "forces", ctx.diag, {"gravity"});
  if (auto g = r.vec3("gravity")) {
    s.gravity = *g;
    s.has_gravity = !g->isZero(0);
  }
}

// The table at `part` of `t` ("name", or "name[i]": element i of an array of
// tables), made when missing; null when the document holds something else there.
toml::table* sub_table(toml::table& t, const std::string& part) {
  const auto open = part.find('[');
  if (open == std::string::npos) {
    if (!t.contains(part)) t.insert(part, toml::table{});
    return t.get(part)->as_table();
  }
  const std::string name = part.substr(0, open);
  const std::size_t index = std::stoul(part.substr(open + 1));
  if (!t.contains(name)) t.insert(name, toml::array{});
  toml::array* a = t.get(name)->as_array();
  if (!a) return nullptr;
  while (a->size() <= index) a->push_back(toml::table{});
  return a->get(index)->as_table();
}

// Puts each override into the parsed document, creating tables (and arrays of
// tables, "bodies[0].shape.units") on the way. A path through anything else
// is left alone: the loader reports that key.
void apply_overrides(toml::table& root, const std::vector<Override>& overrides) {
  for (const Override& o : overrides) {
    toml::table* t = &root;
    std::string_view rest = o.key;
    for (auto dot = rest.find('.'); t && dot != std::string_view::npos; dot = rest.find('.')) {
      t = sub_table(*t, std::string(rest.substr(0, dot)));
      rest.remove_prefix(dot + 1);
    }
    if (!t) continue;
    const std::string leaf(rest);
    std::visit(
        [&](const auto& v) {
          using V = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<V, std::monostate>) t->erase(leaf);
          else if constexpr (std::is_same_v<V, long long>) t->insert_or_assign(leaf, static_cast<int64_t>(v));
          else t->insert_or_assign(leaf, v);
        },
        o.value);
  }
}

// The settings of `s` as the [simulation] and [output] tables that load them.
toml::table settings_table(const Scene& s) {
  const SimulationConfig& sim = s.simulation;
  toml::table simulation{{"method", sim.automatic ? std::string("auto") : std::string(method_name(sim.step.method))},
                         {"duration", sim.duration}, {"fps", sim.fps}, {"rtol", sim.step.rtol}, {"atol", sim.step.atol}};
  if (sim.tolerance) simulation.insert("tolerance", *sim.tolerance);
  else simulation.insert("dt", sim.step.dt);  // auto with a tolerance picks dt: the file could give none
  const OutputConfig& o = s.render.output;
  toml::table output{{"width", o.width}, {"height", o.height}, {"fps", o.fps},
                     {"aa", std::string(antialias_name(o.aa))}, {"msaa", o.msaa},
                     {"background", toml::array{o.background.x(), o.background.y(), o.background.z()}},
                     {"video", std::string(video_format_name(o.video))}, {"time_scale", s.render.explain.time_scale}};
  return toml::table{{"simulation", simulation}, {"output", output}};
}

Scene load_impl(std::string_view text, const std::string& source_name, const std::filesystem::path& base_dir,
                const std::vector<Override>& overrides) {
  std::vector<std::pair<std::string, std::string>> options;  // key -> option, for messages
  for (const Override& o : overrides) options.emplace_back(o.key, o.option);
  detail::Diagnostics diag(source_name, std::move(options));
  check_toml_limits(text, source_name);
  toml::table root;
  try {
    root = toml::parse(text, source_name);
  } catch (const toml::parse_error& e) {
    diag.error(e.source(), "", "TOML syntax: " + std::string(e.description()));
    throw SceneError(diag.take_errors());
  }
  apply_overrides(root, overrides);
  Scene s;
  s.content_hash = fnv1a_hex(text);
  detail::LoadContext ctx{diag, base_dir, 0, {}};
  TableReader r(root, "", diag,
                {"name", "simulation", "forces", "bodies", "output", "camera", "draw", "compare", "views", "captions",
                  "title", "slow_motion", "holds"});
  s.name = r.string("name").value_or("scene");
  // The name becomes the default output folder out/<name> and the video's file
  // name: keep it a plain file name, so a render never writes elsewhere.
  const bool name_ok = !s.name.empty() && s.name.size() <= 64 && s.name != "." && s.name != ".." &&
                       std::all_of(s.name.begin(), s.name.end(), [](char c) {
                         return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                                c == '_' || c == '-' || c == '.';
                       });
  if (!name_ok) {
    r.error("name", "expected 1-64 characters from [A-Za-z0-9_.-] (it names the output folder), found " + quote_token(s.name));
    s.name = "scene";
  }
  read_simulation(r, ctx, s);
  read_forces(r, ctx, s);
  detail::read_bodies(r, ctx, s);
  detail::read_render_config(r, ctx, s);
  detail::read_explain_config(r, ctx, s);
  if (!diag.ok()) throw SceneError(diag.take_errors());
  s.warnings = diag.take_warnings();
  return s;
}

}  // namespace

std::string Diagnostic::str() const {
  std::string out = !option.empty() ? option + ": error: "
                    : line == 0  ? file + ": error: "
                                 : file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": error: ";
  if (!key.empty()) out += key + ": ";
  return out + message;
}

namespace {
std::string join(const std::vector<Diagnostic>& d) {
  std::string out;
  for (const Diagnostic& x : d) out += (out.empty() ? "" : "\n") + x.str();
  return out;
}
}  // namespace

SceneError::SceneError(std::vector<Diagnostic> diags) : InputError(join(diags)), diags_(std::move(diags)) {}

const Body* Scene::find_body(std::string_view body_name) const {
  for (const Body& b : bodies)
    if (b.name == body_name) return &b;
  return nullptr;
}

StepConfig step_config(const SimulationConfig& sim, const RigidBodyModel& model) {
  return sim.automatic ? auto_without_tolerance(model, sim.step).config : sim.step;
}

MethodPlan plan_method(const SimulationConfig& sim, const Body& body) {
  MethodPlan p;
  if (!sim.automatic) {
    p.config = sim.step;
    return p;
  }
  if (!sim.tolerance) {
    const MethodChoice c = auto_without_tolerance(body.model, sim.step);
    p.config = c.config;
    p.reason = c.reason;
    return p;
  }
  ChoiceRequest req;
  req.duration = sim.duration;
  req.sample_interval = 1 / sim.fps;
  req.tolerance = *sim.tolerance;
  const MethodChoice c = choose_method(body.model, body.initial, req);
  p.config = c.config;
  p.reason = c.reason;
  p.candidates = c.candidates;
  return p;
}

std::string step_label(const StepConfig& c, const RigidBodyModel& m) {
  const MethodInfo& info = method_info(c.method);
  if (info.adaptive) return "rtol = " + format_number(c.rtol, 6);
  if (info.closed_form_if_free && m.forces.empty()) return "closed form";
  return "dt = " + format_number(c.dt, 6) + " s";
}

Settings override_settings(const Scene& s, const std::vector<Override>& overrides, std::string_view source_name) {
  std::vector<std::pair<std::string, std::string>> options;
  for (const Override& o : overrides) options.emplace_back(o.key, o.option);
  detail::Diagnostics diag(std::string(source_name), std::move(options), false);
  toml::table root = settings_table(s);
  // A tolerance makes auto pick dt: the scene's dt goes, as a file could not hold both.
  auto sets = [&](std::string_view key) {
    return std::any_of(overrides.begin(), overrides.end(), [&](const Override& o) {
      return o.key == key && !std::holds_alternative<std::monostate>(o.value);
    });
  };
  if (sets("simulation.tolerance") && !sets("simulation.dt")) root["simulation"].as_table()->erase("dt");
  apply_overrides(root, overrides);
  Scene read;  // no bodies: only what the two tables fill
  read.render.output = s.render.output;  // keeps what [output] does not hold (the quality)
  detail::LoadContext ctx{diag, {}, 0, {}};
  detail::TableReader r(root, "", diag, {"simulation", "output"});
  read_simulation(r, ctx, read);
  detail::read_output_config(r, ctx, read);
  if (!diag.ok()) throw SceneError(diag.take_errors());
  return {read.simulation, read.render.output, read.render.explain.time_scale, diag.take_warnings()};
}

void Settings::apply_to(Scene& s) const {
  s.simulation = simulation;
  s.render.output = output;
  s.render.explain.time_scale = time_scale;
}

Scene load_scene(const std::filesystem::path& path, const std::vector<Override>& overrides) {
  const std::string text = read_input_file(path, kMaxSceneBytes, "scene file");
  Scene s = load_impl(text, path.string(), path.parent_path(), overrides);
  s.path = path;
  return s;
}

Scene load_scene_from_string(std::string_view text, std::string_view source_name,
                             const std::filesystem::path& base_dir, const std::vector<Override>& overrides) {
  return load_impl(text, std::string(source_name), base_dir, overrides);
}

std::vector<double> sample_times(double duration, double fps) {
  std::vector<double> t;
  const double n = std::floor(duration * fps * (1 + 1e-12));
  for (long k = 0; k <= static_cast<long>(n); ++k) t.push_back(static_cast<double>(k) / fps);
  // A last sample within round-off of the end *is* the end; otherwise append it.
  if (t.size() > 1 && std::abs(t.back() - duration) <= 1e-9 * std::max(1.0, duration)) t.back() = duration;
  else if (t.back() != duration) t.push_back(duration);
  return t;
}

std::string fnv1a_hex(std::string_view bytes) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  char out[17];
  std::snprintf(out, sizeof out, "%016llx", static_cast<unsigned long long>(h));
  return out;
}

}  // namespace tumble::scene
