// tumble.simulate (scene::sample_run: the loop of `tumble simulate`) and
// tumble.export_gltf. Trajectory arrays are views of the C++ vectors.
#include <memory>
#include <optional>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#include "core/integrator.hpp"
#include "core/observables.hpp"
#include "core/propagator.hpp"
#include "scene/sampled_run.hpp"
#ifdef TUMBLE_HAVE_GLTF
#include "gltf/gltf_export.hpp"
#endif

namespace tumble::py_bind {

namespace {

using scene::Trajectory;

/// A (n, cols) read-only view of a column of the trajectory (cols = 0: shape (n,)).
py::array_t<double> column(py::object self, const std::vector<double> Trajectory::*times, std::size_t array,
                           std::size_t cols) {
  const Trajectory& t = self.cast<const Trajectory&>();
  const double* data = times ? (t.*times).data() : t.arrays.at(array).data();
  return view(data, t.size(), cols, cols ? cols * sizeof(double) : sizeof(double), self);
}

/// t, then an array per kPythonArray observable (core/observables.hpp), and
/// the class docstring that lists them with their shapes and units.
void add_arrays(py::class_<Trajectory, std::shared_ptr<Trajectory>>& c) {
  c.def_property_readonly("t", [](py::object self) { return column(std::move(self), &Trajectory::t, 0, 0); });
  for (std::size_t i = 0; i < scene::python_arrays().size(); ++i) {
    const Observable& o = *scene::python_arrays()[i];
    const std::size_t cols = o.size == 1 ? 0 : o.size;
    c.def_property_readonly(std::string(o.name).c_str(),
                            [i, cols](py::object self) { return column(std::move(self), nullptr, i, cols); });
  }
}

std::string trajectory_doc() {
  std::string d = "One body's samples in the CSV's units and frames (read-only numpy views): t (n,) s";
  for (const Observable* o : scene::python_arrays())
    d += "; " + std::string(o->name) + (o->size == 1 ? " (n,)" : " (n, " + std::to_string(o->size) + ")") +
         (o->unit.empty() ? "" : " ") + std::string(o->unit) + (o->note.empty() ? "" : " ") + std::string(o->note);
  return d + ".";
}

/// The scene's [simulation] with simulate()'s method and dt, read by the scene
/// loader as `tumble simulate --method --dt` are (the same checks and texts).
scene::SimulationConfig run_config(const scene::Scene& s, const std::optional<std::string>& method,
                                   std::optional<double> dt) {
  std::vector<scene::Override> o;
  if (method) {
    o.push_back(arg_override("simulate", "method", "simulation.method", *method));
    if (*method != "auto") o.push_back(arg_override("simulate", "method", "simulation.tolerance", {}));  // the named method wins
  }
  if (dt) o.push_back(arg_override("simulate", "dt", "simulation.dt", *dt));
  return scene::override_settings(s, o, "tumble.simulate()").simulation;
}

}  // namespace

/// tumble.simulate and tumble.export_gltf.
static void add_run_functions(py::module_& m) {
  m.def(
      "simulate",
      [](const scene::Scene& s, const std::optional<std::string>& method, std::optional<double> dt,
         const std::optional<py::array_t<double, py::array::c_style | py::array::forcecast>>& times) {
        const scene::SimulationConfig sim = run_config(s, method, dt);
        std::vector<double> t;
        if (times) t.assign(times->data(), times->data() + times->size());
        else t = scene::sample_times(sim.duration, sim.fps);
        std::vector<Trajectory> out;
        {
          py::gil_scoped_release nogil;
          out = scene::sample_run(s, sim, t, check_signals, warn);
        }
        std::vector<std::shared_ptr<Trajectory>> list;
        for (Trajectory& x : out) list.push_back(std::make_shared<Trajectory>(std::move(x)));
        return list;
      },
      py::arg("scene"), py::arg("method") = py::none(), py::arg("dt") = py::none(), py::arg("times") = py::none(),
      "Integrates every body (method and dt default to the scene's) and samples it at `times` (s; default "
      "k/fps up to the duration, as `tumble simulate`). Returns one Trajectory per body, equal to the CSV's rows. "
      "method and dt are checked by the scene loader as `--method` and `--dt` are (tumble.SceneError); a dt too "
      "coarse for a body warns (tumble.TumbleWarning) as the command line does. Releases the GIL; Ctrl-C raises "
      "KeyboardInterrupt.");

#ifdef TUMBLE_HAVE_GLTF
  m.def(
      "export_gltf",
      [](const scene::Scene& s, const std::filesystem::path& path, std::optional<double> fps,
         std::optional<double> key_tolerance) {
        gltf::KeyOptions keys;  // fps is the scene's output.fps, checked by the loader as --fps is
        if (fps) keys.fps = scene::override_settings(s, {arg_override("export_gltf", "fps", "output.fps", *fps)},
                                                     "tumble.export_gltf()").output.fps;
        keys.tolerance = key_tolerance.value_or(keys.tolerance);
        keys.tolerance_name = "tumble.export_gltf(key_tolerance=...)";
        py::gil_scoped_release nogil;
        gltf::export_gltf(s, path, keys, "path", check_signals);
      },
      py::arg("scene"), py::arg("path"), py::arg("fps") = py::none(), py::kw_only(), py::arg("key_tolerance") = py::none(),
      "Writes the simulated scene as glTF 2.0 (.glb or .gltf), as `tumble export --gltf`: y up, keys at fps "
      "(default the scene's) at least and more where a body turns fast, so that a viewer's interpolation is within "
      "key_tolerance (rad, default 0.001) of the simulation.");
#endif
}

void add_run(py::module_& m) {
  static const std::string doc = trajectory_doc();
  py::class_<Trajectory, std::shared_ptr<Trajectory>> c(m, "Trajectory", doc.c_str());
  c.def_readonly("body", &Trajectory::body)
      .def_readonly("method", &Trajectory::method)
      .def_readonly("step", &Trajectory::step)
      .def_readonly("steps", &Trajectory::steps)
      .def_readonly("auto_reason", &Trajectory::auto_reason)
      .def("__len__", &Trajectory::size)
      .def("__repr__", [](const Trajectory& t) {
        return "<tumble.Trajectory '" + t.body + "': " + std::to_string(t.size()) + " samples, " + t.method + ", " +
               t.step + ">";
      });
  add_arrays(c);

  add_run_functions(m);
}

}  // namespace tumble::py_bind
