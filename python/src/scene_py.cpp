// tumble.Scene and its bodies and settings as Python values. Loading goes
// through the scene reader (same validation and messages as the command
// line); an edited initial condition re-derives the state with make_state.
#include <memory>
#include <sstream>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#include "core/dynamics.hpp"
#include "core/integrator.hpp"
#include "scene/scene.hpp"

namespace tumble::py_bind {

namespace {

using scene::Body;
using scene::Scene;

void reset_state(Body& b) { b.initial = make_state(b.model, b.initial_conditions); }

/// A vector property of the initial conditions, rebuilding the state when set.
template <Eigen::Vector3d InitialConditions::*member>
void ic_vec3(py::class_<Body>& c, const char* name, const char* doc) {
  c.def_property(
      name, [](const Body& b) { return vec3(b.initial_conditions.*member); },
      [name](Body& b, const py::object& v) {
        b.initial_conditions.*member = to_vec3(v, name);
        reset_state(b);
      },
      doc);
}

/// A body's initial state (position, velocity, ω, orientation) and colour, as editable properties.
void add_body_state(py::class_<Body>& c) {
  ic_vec3<&InitialConditions::position>(c, "position", "initial centre of mass, world, m");
  ic_vec3<&InitialConditions::velocity>(c, "velocity", "initial velocity, world, m/s");
  // ω as the scene file gives it: a value and the frame it is in.
  auto set_omega = [](Body& b, const py::object& v, Frame frame, const char* name) {
    b.initial_conditions.omega = to_vec3(v, name);
    b.initial_conditions.omega_frame = frame;
    reset_state(b);
  };
  c.def_property(
       "omega_body", [](const Body& b) { return vec3(omega_body(b.model, b.initial)); },
       [set_omega](Body& b, const py::object& v) { set_omega(b, v, Frame::body, "omega_body"); },
       "initial ω in the cloud's own axes, rad/s")
      .def_property(
          "omega_world", [](const Body& b) { return vec3(omega_world(b.model, b.initial)); },
          [set_omega](Body& b, const py::object& v) { set_omega(b, v, Frame::world, "omega_world"); },
          "initial ω in the world frame, rad/s")
      .def_property(
          "orientation",
          [](const Body& b) {
            const Eigen::Quaterniond& q = b.initial_conditions.orientation;
            py::array_t<double> a(4);
            for (int i = 0; i < 4; ++i) a.mutable_at(i) = i == 0 ? q.w() : q.vec()[i - 1];
            return a;
          },
          [](Body& b, const py::object& v) {
            const auto q = py::cast<std::vector<double>>(v);
            const Eigen::Quaterniond x(q.size() == 4 ? q[0] : 0, q.size() == 4 ? q[1] : 0, q.size() == 4 ? q[2] : 0,
                                       q.size() == 4 ? q[3] : 0);
            if (q.size() != 4 || !x.coeffs().allFinite() || x.norm() == 0)
              throw py::value_error("orientation: expected a non-zero quaternion (w, x, y, z)");
            b.initial_conditions.orientation = x.normalized();
            reset_state(b);
          },
          "initial world ← cloud rotation (w, x, y, z), a numpy array; normalised when set")
      .def_property(
          "color", [](const Body& b) { return vec3(b.color); },
          [](Body& b, const py::object& v) {
            const Eigen::Vector3d x = to_vec3(v, "color");
            if ((x.array() < 0).any() || (x.array() > 1).any()) throw py::value_error("color: expected 3 numbers in [0, 1]");
            for (scene::MeshSource& s : b.meshes)
              if (s.color == b.color) s.color = x;
            for (scene::ColorSpan& s : b.part_colors)
              if (s.color == b.color) s.color = x;
            b.color = x;
          },
          "linear RGB in [0, 1]")
      .def("__repr__", [](const Body& b) {
        return "<tumble.Body '" + b.name + "': " + std::to_string(b.cloud.size()) + " particles>";
      });
}

void add_body(py::module_& m) {
  py::class_<Body> c(m, "Body", "One body of a scene (a view into the Scene, which keeps it alive).");
  c.def_readonly("name", &Body::name)
      .def_property_readonly("mass", [](const Body& b) { return b.mass_properties.mass; }, "kg")
      .def_property_readonly("com", [](const Body& b) { return vec3(b.mass_properties.com); }, "cloud axes, m")
      .def_property_readonly("inertia", [](const Body& b) { return mat3(b.mass_properties.inertia); },
                             "about the centre of mass, cloud axes, kg·m²")
      .def_property_readonly("principal_moments", [](const Body& b) { return vec3(b.mass_properties.principal_moments); },
                             "ascending, kg·m²")
      .def_property_readonly("principal_axes", [](const Body& b) { return mat3(b.mass_properties.principal_axes); },
                             "columns, cloud axes")
      .def_property_readonly(
          "points",
          [](py::object self) {
            const Body& b = self.cast<const Body&>();
            return view(b.cloud.empty() ? nullptr : b.cloud[0].position.data(), b.cloud.size(), 3, sizeof(Particle), self);
          },
          "particle positions, cloud axes, m: (N, 3), a read-only view")
      .def_property_readonly(
          "masses",
          [](py::object self) {
            const Body& b = self.cast<const Body&>();
            return view(b.cloud.empty() ? nullptr : &b.cloud[0].mass, b.cloud.size(), 0, sizeof(Particle), self);
          },
          "particle masses, kg: (N,), a read-only view");
  add_body_state(c);
}

/// scene.simulation and scene.output: views of a scene's settings, whose
/// setters go through the scene loader (scene::override_settings), so a value
/// is checked and refused with the same words as in a scene file.
struct SimulationView {
  std::shared_ptr<Scene> scene;
};
struct OutputView {
  std::shared_ptr<Scene> scene;
};

template <class View>
void set_key(const View& v, const std::string& key, decltype(scene::Override::value) value) {
  scene::override_settings(*v.scene, {{"scene." + key, key, std::move(value)}}, "scene." + key).apply_to(*v.scene);
}

/// A read-write property of a settings view: `get` reads it, setting writes scene key `key`.
template <class View, class T, class Get>
void key_property(py::class_<View>& c, const char* name, const std::string& key, Get get, const char* doc) {
  c.def_property(
      name, get, [key](const View& v, T x) { set_key(v, key, x); }, doc);
}

std::string simulation_repr(const scene::SimulationConfig& s) {
  const py::object tol = s.tolerance ? py::object(py::float_(*s.tolerance)) : py::object(py::none());
  return py::str("SimulationConfig(method={!r}, dt={!r}, duration={!r}, fps={!r}, rtol={!r}, atol={!r}, tolerance={!r})")
      .format(s.automatic ? std::string("auto") : std::string(method_name(s.step.method)), s.step.dt, s.duration, s.fps,
              s.step.rtol, s.step.atol, tol);
}

void add_simulation(py::module_& m) {
  py::class_<SimulationView> c(m, "SimulationConfig",
                               "[simulation] of a scene: method, dt (s), duration (s), fps, rtol, atol, tolerance. "
                               "Setting one is checked by the scene loader (tumble.SceneError, the file's words).");
  auto sim = [](const SimulationView& v) -> const scene::SimulationConfig& { return v.scene->simulation; };
  c.def_property(
      "method",
      [sim](const SimulationView& v) {
        return sim(v).automatic ? std::string("auto") : std::string(method_name(sim(v).step.method));
      },
      [](const SimulationView& v, const std::string& name) {
        std::vector<scene::Override> o{{"scene.simulation.method", "simulation.method", name}};
        if (name != "auto") o.push_back({"scene.simulation.method", "simulation.tolerance", {}});  // as --method NAME
        scene::override_settings(*v.scene, o, "scene.simulation.method").apply_to(*v.scene);
      },
      "auto or a method name (tumble.methods()); a named method drops auto's tolerance, as --method does");
  key_property<SimulationView, double>(c, "dt", "simulation.dt", [sim](const SimulationView& v) { return sim(v).step.dt; }, "s");
  key_property<SimulationView, double>(c, "duration", "simulation.duration", [sim](const SimulationView& v) { return sim(v).duration; }, "s");
  key_property<SimulationView, double>(c, "fps", "simulation.fps", [sim](const SimulationView& v) { return sim(v).fps; }, "samples per second");
  key_property<SimulationView, double>(c, "rtol", "simulation.rtol", [sim](const SimulationView& v) { return sim(v).step.rtol; }, "adaptive methods");
  key_property<SimulationView, double>(c, "atol", "simulation.atol", [sim](const SimulationView& v) { return sim(v).step.atol; }, "adaptive methods");
  c.def_property(
      "tolerance", [sim](const SimulationView& v) { return sim(v).tolerance; },
      [](const SimulationView& v, std::optional<double> x) {
        if (x) set_key(v, "simulation.tolerance", *x);
        else set_key(v, "simulation.tolerance", {});
      },
      "method = 'auto' only: the largest end error (rad); None for none");
  c.def("__repr__", [sim](const SimulationView& v) { return simulation_repr(sim(v)); });
}

void add_output(py::module_& m) {
  py::class_<OutputView> c(m, "OutputConfig",
                           "[output] of a scene: width, height (px), fps, aa, msaa, video. Setting one is checked by "
                           "the scene loader (tumble.SceneError, the file's words).");
  auto out = [](const OutputView& v) -> const scene::OutputConfig& { return v.scene->render.output; };
  key_property<OutputView, long long>(c, "width", "output.width", [out](const OutputView& v) { return out(v).width; }, "px");
  key_property<OutputView, long long>(c, "height", "output.height", [out](const OutputView& v) { return out(v).height; }, "px");
  key_property<OutputView, double>(c, "fps", "output.fps", [out](const OutputView& v) { return out(v).fps; }, "frames per second");
  key_property<OutputView, std::string>(c, "aa", "output.aa", [out](const OutputView& v) {
    return std::string(scene::antialias_name(out(v).aa));
  }, "'fxaa', 'msaa' (with msaa samples) or 'none'");
  key_property<OutputView, long long>(c, "msaa", "output.msaa", [out](const OutputView& v) { return out(v).msaa; }, "0, 2 or 4");
  key_property<OutputView, std::string>(c, "video", "output.video", [out](const OutputView& v) {
    return std::string(scene::video_format_name(out(v).video));
  }, scene::video_format_choices('\'').c_str());
  c.def("__repr__", [out](const OutputView& v) {
    const scene::OutputConfig& o = out(v);
    return py::str("OutputConfig(width={!r}, height={!r}, fps={!r}, aa={!r}, msaa={!r}, video={!r})")
        .format(o.width, o.height, o.fps, std::string(scene::antialias_name(o.aa)), o.msaa,
                std::string(scene::video_format_name(o.video)));
  });
}

/// The command line's load warnings as Python warnings.
std::shared_ptr<Scene> loaded(Scene&& s) {
  auto p = std::make_shared<Scene>(std::move(s));
  for (const std::string& w : p->warnings) warn(w);
  return p;
}

}  // namespace

/// A scene's settings views and copies.
static void add_scene_settings(py::class_<Scene, std::shared_ptr<Scene>>& c) {
  c.def_property_readonly(
          "simulation", [](const std::shared_ptr<Scene>& s) { return SimulationView{s}; }, "[simulation] (a view: setting edits the scene)")
      .def_property_readonly(
          "output", [](const std::shared_ptr<Scene>& s) { return OutputView{s}; }, "[output] (a view: setting edits the scene)")
      .def("copy", [](const Scene& s) { return std::make_shared<Scene>(s); }, "An independent copy (to edit)")
      .def("__copy__", [](const Scene& s) { return std::make_shared<Scene>(s); })
      .def("__deepcopy__", [](const Scene& s, const py::dict&) { return std::make_shared<Scene>(s); }, py::arg("memo"),
           "copy.deepcopy(scene): an independent copy, as scene.copy()")
      .def("__repr__", [](const Scene& s) {
        return "<tumble.Scene '" + s.name + "': " + std::to_string(s.bodies.size()) + " bodies, " +
               std::to_string(s.simulation.duration) + " s>";
      });
}

void add_scene(py::module_& m) {
  add_body(m);
  add_simulation(m);
  add_output(m);
  py::class_<Scene, std::shared_ptr<Scene>> c(m, "Scene", "A scene file read and validated by tumble's scene reader.");
  c.def_static(
          "load",
          [](const std::filesystem::path& path) {
            Scene s;
            {
              py::gil_scoped_release nogil;  // mesh fills take a while
              s = scene::load_scene(path);
            }
            return loaded(std::move(s));
          },
          py::arg("path"), "Reads a scene file (TOML). Raises tumble.SceneError with the command line's message.")
      .def_static(
          "from_toml",
          [](const std::string& text, const std::filesystem::path& base_dir, const std::string& name) {
            Scene s;
            {
              py::gil_scoped_release nogil;
              s = scene::load_scene_from_string(text, name, base_dir);
            }
            return loaded(std::move(s));
          },
          py::arg("text"), py::arg("base_dir") = ".", py::arg("name") = "<string>",
          "Reads a scene from TOML text; files it names resolve against base_dir; errors name `name`.")
      .def_readonly("name", &Scene::name)
      .def_readonly("path", &Scene::path)
      .def_readonly("warnings", &Scene::warnings)
      .def_property_readonly("gravity", [](const Scene& s) { return vec3(s.gravity); }, "m/s², world")
      .def_property_readonly(
          "bodies",
          [](py::object self) {
            Scene& s = self.cast<Scene&>();
            py::list out;
            for (Body& b : s.bodies) out.append(py::cast(&b, py::return_value_policy::reference_internal, self));
            return out;
          },
          "The bodies (views: editing one edits the scene).")
      .def(
          "body",
          [](py::object self, const std::string& name) {
            Scene& s = self.cast<Scene&>();
            for (Body& b : s.bodies)
              if (b.name == name) return py::cast(&b, py::return_value_policy::reference_internal, self);
            throw py::key_error("no body named '" + name + "'");
          },
          py::arg("name"));
  add_scene_settings(c);
}

}  // namespace tumble::py_bind
