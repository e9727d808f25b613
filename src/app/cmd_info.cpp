// `tumble info SCENE [--json]`: mass properties of every body, world frame at t = 0.
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "app/commands.hpp"
#include "app/mesh_info.hpp"
#include "base/format.hpp"
#include "compose/layout_notes.hpp"
#include "io/json.hpp"
#include "scene/events.hpp"
#include "scene/frame_clock.hpp"

namespace tumble::app {

namespace {

struct InfoOptions {
  std::string scene;
  bool json = false;
};

/// A body's mass properties expressed in the world at t = 0.
struct BodyInfo {
  std::string name;
  std::size_t particles;
  double mass;
  Eigen::Vector3d com, moments, box_center, half_extents;
  Eigen::Matrix3d inertia, axes;
};

BodyInfo world_info(const scene::Body& b) {
  const MassProperties& mp = b.mass_properties;
  const Eigen::Matrix3d R = b.initial_conditions.orientation.normalized().toRotationMatrix();
  BodyInfo i;
  i.name = b.name;
  i.particles = b.cloud.size();
  i.mass = mp.mass;
  i.com = b.initial.c;
  i.inertia = R * mp.inertia * R.transpose();
  i.moments = mp.principal_moments;
  i.axes = R * mp.principal_axes;
  // box.center is relative to c along the principal axes.
  i.box_center = b.initial.c + i.axes * mp.box.center;
  i.half_extents = mp.box.half_extents;
  return i;
}

/// [x, y, z] as text, for the table of to_text.
std::string vec_text(const Eigen::Vector3d& v) {
  return "[" + format_number(v.x()) + ", " + format_number(v.y()) + ", " + format_number(v.z()) + "]";
}

io::Json vec_json(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

io::Json mat_json(const Eigen::Matrix3d& m) {  // rows
  return {vec_json(m.row(0).transpose()), vec_json(m.row(1).transpose()), vec_json(m.row(2).transpose())};
}

// "  flips (e2 ⊥ L)     1.7999, 5.0887 s in 6 s": the events "flip N" counts.
std::string flips_text(const scene::Scene& s, std::size_t body) {
  const std::vector<double> flips = scene::body_flip_times(s, body);
  std::string out = "  flips (e2 ⊥ L)     ";
  char t[32];
  for (std::size_t i = 0; i < flips.size(); ++i) {
    std::snprintf(t, sizeof t, "%s%.4f", i ? ", " : "", flips[i]);
    out += t;
  }
  return out + (flips.empty() ? "none" : " s") + " in " + format_number(s.simulation.duration) + " s\n";
}

// The frames and the simulated time each shows: one line per stretch of one speed.
std::string frames_text(const scene::Scene& s) {
  const scene::FrameClock c = scene::frame_clock(s, s.render.output.fps);
  std::ostringstream o;
  o << "\nframes " << c.count() << " at " << format_number(c.fps()) << " fps (video "
    << format_number(static_cast<double>(c.count() - 1) / c.fps(), kShortestDigits) << " s; frame k at video k/fps s)\n";
  char line[200];
  for (const scene::ClockSpan& sp : scene::clock_spans(c)) {
    const double v0 = static_cast<double>(sp.first) / c.fps(), v1 = static_cast<double>(sp.last) / c.fps();
    if (sp.rate == 0 && c.on_title_card(sp.first))
      std::snprintf(line, sizeof line, "  %6ld-%-6ld video %7.3f-%-7.3f s  title card, t = 0 s\n", sp.first, sp.last,
                    v0, v1);
    else if (sp.rate == 0)
      std::snprintf(line, sizeof line, "  %6ld-%-6ld video %7.3f-%-7.3f s  hold, t = %.4f s\n", sp.first, sp.last, v0,
                    v1, c.time(sp.first));
    else
      std::snprintf(line, sizeof line, "  %6ld-%-6ld video %7.3f-%-7.3f s  t = %.4f-%.4f s  %s\n", sp.first, sp.last,
                    v0, v1, c.time(sp.first), c.time(sp.last), (sp.rate == 1 ? "real time" : scene::speed_text(sp.rate)).c_str());
    o << line;
  }
  return o.str();
}

io::Json to_json(const scene::Scene& s) {
  io::Json bodies = io::Json::array();
  for (const scene::Body& b : s.bodies) {
    const BodyInfo i = world_info(b);
    io::Json j;
    j["name"] = i.name;
    j["mass"] = i.mass;
    j["com"] = vec_json(i.com);
    j["inertia"] = mat_json(i.inertia);
    j["principal_moments"] = vec_json(i.moments);
    j["principal_axes"] = mat_json(i.axes);
    j["box"] = {{"center", vec_json(i.box_center)}, {"half_extents", vec_json(i.half_extents)}};
    if (!b.meshes.empty()) {
      io::Json meshes = io::Json::array();
      for (const scene::MeshSource& ms : b.meshes) meshes.push_back(mesh_json(ms));
      j["meshes"] = std::move(meshes);
    }
    j["flip_times"] = scene::body_flip_times(s, static_cast<std::size_t>(&b - s.bodies.data()));
    bodies.push_back(std::move(j));
  }
  const scene::FrameClock clock = scene::frame_clock(s, s.render.output.fps);
  io::Json times = io::Json::array();
  for (long k = 0; k < clock.count(); ++k) times.push_back(clock.time(k));
  io::Json frames{{"count", clock.count()}, {"fps", clock.fps()}, {"hold", clock.hold()}, {"times", std::move(times)}};
  return io::Json{{"bodies", std::move(bodies)}, {"frames", std::move(frames)}};
}

std::string to_text(const scene::Scene& s) {
  std::ostringstream o;
  o << "scene " << s.name << " (" << s.path.string() << ", fnv1a " << s.content_hash << ")\n";
  auto row = [](const Eigen::Vector3d& v) { return vec_text(v); };
  for (const scene::Body& b : s.bodies) {
    const BodyInfo i = world_info(b);
    o << "\nbody " << i.name << " (" << i.particles << " particles)\n"
      << "  mass              " << format_number(i.mass) << " kg\n"
      << "  centre of mass    " << row(i.com) << " m\n"
      << "  inertia about c   " << row(i.inertia.row(0).transpose()) << " kg m^2 (world, t = 0)\n"
      << "                    " << row(i.inertia.row(1).transpose()) << "\n"
      << "                    " << row(i.inertia.row(2).transpose()) << "\n"
      << "  principal moments " << row(i.moments) << " kg m^2\n"
      << "  principal axes    " << row(i.axes.col(0)) << " (1, smallest)\n"
      << "                    " << row(i.axes.col(1)) << " (2)\n"
      << "                    " << row(i.axes.col(2)) << " (3, largest)\n"
      << "  box centre        " << row(i.box_center) << " m\n"
      << "  box half extents  " << row(i.half_extents) << " m (along the principal axes)\n";
    for (const scene::MeshSource& m : b.meshes) o << mesh_text(m);
    const scene::MethodPlan plan = scene::plan_method(s.simulation, b);
    o << "  method            " << method_name(plan.config.method) << ", " << scene::step_label(plan.config, b.model);
    o << (plan.reason.empty() ? " (set by the scene)" : " (auto: " + plan.reason + ")") << "\n";
    for (const MethodEstimate& e : plan.candidates) {
      char line[200];
      if (e.usable && e.steps == 0)  // an adaptive pair picked without a pilot: nothing measured
        std::snprintf(line, sizeof line, "    %-18s %-9s %-10.3g not priced (no pilot)  error ~%.1e rad%s\n",
                      std::string(method_name(e.method)).c_str(), "rtol", e.config.rtol, e.error,
                      e.method == plan.config.method ? "  <- picked" : "");
      else if (e.usable)
        std::snprintf(line, sizeof line, "    %-18s %-9s %-10.3g %10.0f steps  error %.1e rad  ~%.3g ms%s\n",
                      std::string(method_name(e.method)).c_str(), method_info(e.method).adaptive ? "rtol" : "dt (s)",
                      method_info(e.method).adaptive ? e.config.rtol : e.config.dt, e.steps, e.error, e.cost_s * 1e3,
                      e.method == plan.config.method ? "  <- picked" : "");
      else
        std::snprintf(line, sizeof line, "    %-18s not usable: %s\n", std::string(method_name(e.method)).c_str(),
                      e.note.c_str());
      o << line;
    }
    o << flips_text(s, static_cast<std::size_t>(&b - s.bodies.data()));
  }
  o << frames_text(s);
  return o.str();
}

// What the layout leaves out of which frames at the scene's size (as `tumble render` would warn).
std::string layout_text(const std::vector<std::string>& notes, const scene::Scene& s) {
  std::string o = "\nlayout at " + std::to_string(s.render.output.width) + "x" +
                  std::to_string(s.render.output.height) + " (every frame, as `tumble render` composes it)\n";
  if (notes.empty()) return o + "  nothing left out\n";
  for (const std::string& n : notes) o += "  " + n + "\n";
  return o;
}

int run_info(const InfoOptions& o) {
  const scene::Scene s = load_scene_verbose(o.scene);
  const std::vector<std::string> notes = compose::check_layout(s).lines();
  if (o.json) {
    io::Json j = to_json(s);
    j["layout"] = {{"width", s.render.output.width}, {"height", s.render.output.height}, {"notes", notes}};
    std::cout << io::json_text(j);
  } else {
    std::cout << to_text(s) << layout_text(notes, s);
  }
  return kOk;
}

}  // namespace

void add_info_command(CLI::App& app, Action& action) {
  const auto [cmd, o] = add_command(app, action, "info",
                                    "Print each body's mass properties (world frame, t = 0)", run_info);
  cmd->add_flag("--json", o->json, "Machine-readable output");
}

}  // namespace tumble::app
