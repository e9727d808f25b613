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

double positive(double v, const char* what) {
  if (!std::isfinite(v) || v <= 0) throw py::value_error(std::string(what) + ": expected a finite number > 0");
  return v;
}

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
            return std::vector<double>{q.w(), q.x(), q.y(), q.z()};
          },
          [](Body& b, const std::vector<double>& q) {
            const Eigen::Quaterniond x(q.size() == 4 ? q[0] : 0, q.size() == 4 ? q[1] : 0, q.size() == 4 ? q[2] : 0,
                                       q.size() == 4 ? q[3] : 0);
            if (q.size() != 4 || !x.coeffs().allFinite() || x.norm() == 0)
              throw py::value_error("orientation: expected a non-zero quaternion (w, x, y, z)");
            b.initial_conditions.orientation = x.normalized();
            reset_state(b);
          },
          "initial world ← cloud rotation (w, x, y, z), normalised when set")
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

void add_settings(py::module_& m) {
  py::class_<scene::SimulationConfig>(m, "SimulationConfig", "[simulation]: method, dt (s), duration (s), fps, ...")
      .def_property(
          "method",
          [](const scene::SimulationConfig& s) { return s.automatic ? std::string("auto") : std::string(method_name(s.step.method)); },
          [](scene::SimulationConfig& s, const std::string& name) {
            if (name == "auto") {
              s.automatic = true;
              return;
            }
            const std::optional<Method> mt = parse_method(name);
            if (!mt) throw py::value_error("method: expected auto or " + method_list() + ", found \"" + name + "\"");
            s.automatic = false;
            s.step.method = *mt;
            s.tolerance.reset();  // as --method does: a named method needs no tolerance
          })
      .def_property(
          "dt", [](const scene::SimulationConfig& s) { return s.step.dt; },
          [](scene::SimulationConfig& s, double v) { s.step.dt = positive(v, "dt"); })
      .def_property(
          "duration", [](const scene::SimulationConfig& s) { return s.duration; },
          [](scene::SimulationConfig& s, double v) { s.duration = positive(v, "duration"); })
      .def_property(
          "fps", [](const scene::SimulationConfig& s) { return s.fps; },
          [](scene::SimulationConfig& s, double v) { s.fps = positive(v, "fps"); })
      .def_property(
          "rtol", [](const scene::SimulationConfig& s) { return s.step.rtol; },
          [](scene::SimulationConfig& s, double v) { s.step.rtol = positive(v, "rtol"); })
      .def_property(
          "atol", [](const scene::SimulationConfig& s) { return s.step.atol; },
          [](scene::SimulationConfig& s, double v) { s.step.atol = positive(v, "atol"); })
      .def_readwrite("tolerance", &scene::SimulationConfig::tolerance);

  py::class_<scene::OutputConfig>(m, "OutputConfig", "[output]: width, height (px), fps, aa")
      .def_property(
          "width", [](const scene::OutputConfig& o) { return o.width; },
          [](scene::OutputConfig& o, int v) { o.width = static_cast<int>(positive(v, "width")); })
      .def_property(
          "height", [](const scene::OutputConfig& o) { return o.height; },
          [](scene::OutputConfig& o, int v) { o.height = static_cast<int>(positive(v, "height")); })
      .def_property(
          "fps", [](const scene::OutputConfig& o) { return o.fps; },
          [](scene::OutputConfig& o, double v) { o.fps = positive(v, "fps"); })
      .def_property_readonly("aa", [](const scene::OutputConfig& o) { return std::string(scene::antialias_name(o.aa)); })
      .def_readonly("msaa", &scene::OutputConfig::msaa);
}

}  // namespace

void add_scene(py::module_& m) {
  add_body(m);
  add_settings(m);
  py::class_<Scene, std::shared_ptr<Scene>>(m, "Scene", "A scene file read and validated by tumble's scene reader.")
      .def_static(
          "load",
          [](const std::filesystem::path& path) {
            py::gil_scoped_release nogil;  // mesh fills take a while
            return std::make_shared<Scene>(scene::load_scene(path));
          },
          py::arg("path"), "Reads a scene file (TOML). Raises tumble.SceneError with the command line's message.")
      .def_static(
          "from_toml",
          [](const std::string& text, const std::filesystem::path& base_dir, const std::string& name) {
            py::gil_scoped_release nogil;
            return std::make_shared<Scene>(scene::load_scene_from_string(text, name, base_dir));
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
          py::arg("name"))
      .def_property_readonly(
          "simulation", [](py::object self) { return py::cast(&self.cast<Scene&>().simulation, py::return_value_policy::reference_internal, self); })
      .def_property_readonly(
          "output", [](py::object self) { return py::cast(&self.cast<Scene&>().render.output, py::return_value_policy::reference_internal, self); })
      .def("copy", [](const Scene& s) { return std::make_shared<Scene>(s); }, "An independent copy (to edit)")
      .def("__repr__", [](const Scene& s) {
        return "<tumble.Scene '" + s.name + "': " + std::to_string(s.bodies.size()) + " bodies, " +
               std::to_string(s.simulation.duration) + " s>";
      });
}

}  // namespace tumble::py_bind
