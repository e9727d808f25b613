// The `tumble` Python module: the C++ layers (scene reader, core, glTF export,
// render pipeline) bound with pybind11. No second implementation: every
// number comes from the same functions as the command line's.
#include <pybind11/stl.h>

#include "base/input_file.hpp"
#include "bindings.hpp"
#include "core/error.hpp"
#include "core/integrator.hpp"
#include "io/atomic_file.hpp"
#include "scene/scene.hpp"

namespace tumble::py_bind {

namespace {

PyObject* g_error = nullptr;       // tumble.Error
PyObject* g_scene_error = nullptr; // tumble.SceneError (also ValueError)
PyObject* g_unreadable = nullptr;  // tumble.UnreadableFileError (also OSError)
PyObject* g_diverged = nullptr;    // tumble.DivergedError (also ArithmeticError)
PyObject* g_output = nullptr;      // tumble.OutputError (also OSError)
PyObject* g_warning = nullptr;     // tumble.TumbleWarning (a UserWarning)

PyObject* new_error(py::module_& m, const char* name, const char* doc, py::tuple bases) {
  const std::string full = std::string("tumble.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(full.c_str(), doc, bases.ptr(), nullptr);
  if (!type) throw py::error_already_set();
  m.add_object(name, py::handle(type));
  return type;
}

/// Raises `type(message)` with extra attributes.
void raise(PyObject* type, const char* message, const py::dict& attrs = {}) {
  py::object e = py::reinterpret_borrow<py::object>(type)(message);
  for (auto item : attrs) py::setattr(e, item.first, item.second);
  PyErr_SetObject(type, e.ptr());
}

py::list diagnostics(const scene::SceneError& e) {
  py::list out;
  for (const scene::Diagnostic& d : e.diagnostics()) {
    py::dict x;
    x["file"] = d.file;
    x["line"] = d.line;
    x["column"] = d.column;
    x["key"] = d.key;
    x["message"] = d.message;
    x["option"] = d.option;
    out.append(x);
  }
  return out;
}

}  // namespace

Eigen::Vector3d to_vec3(const py::handle& h, const char* what) {
  const auto v = py::cast<std::vector<double>>(h);
  if (v.size() != 3) throw py::value_error(std::string(what) + ": expected 3 numbers, found " + std::to_string(v.size()));
  const Eigen::Vector3d x(v[0], v[1], v[2]);
  if (!x.allFinite()) throw py::value_error(std::string(what) + ": expected finite numbers");
  return x;
}

void warn(const std::string& text) {
  py::gil_scoped_acquire gil;
  if (PyErr_WarnEx(g_warning, text.c_str(), 1) != 0) throw py::error_already_set();
}

void check_signals() {
  py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
}

void add_errors(py::module_& m) {
  g_error = new_error(m, "Error", "Base of tumble's errors.", py::make_tuple(py::handle(PyExc_Exception)));
  g_scene_error = new_error(m, "SceneError",
                            "Bad input: a scene, mesh or argument. The message is the command line's "
                            "(file:line:col: error: key: message); .diagnostics lists each problem.",
                            py::make_tuple(py::handle(g_error), py::handle(PyExc_ValueError)));
  g_unreadable = new_error(m, "UnreadableFileError", "A path that cannot be read (a folder, permission denied).",
                           py::make_tuple(py::handle(g_scene_error), py::handle(PyExc_OSError)));
  g_diverged = new_error(m, "DivergedError", "A run became non-finite or its energy blew up; .time (s), .step.",
                         py::make_tuple(py::handle(g_error), py::handle(PyExc_ArithmeticError)));
  g_output = new_error(m, "OutputError", "A file could not be written.",
                       py::make_tuple(py::handle(g_error), py::handle(PyExc_OSError)));
  g_warning = new_error(m, "TumbleWarning",
                        "What the command line prints as 'tumble: warning: ...' (a dt too coarse for a body, a "
                        "scene value adjusted), as a Python warning.",
                        py::make_tuple(py::handle(PyExc_UserWarning)));
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const scene::SceneError& e) {
      py::dict attrs;
      attrs["diagnostics"] = diagnostics(e);
      raise(g_scene_error, e.what(), attrs);
    } catch (const InputError& e) {
      py::dict attrs;
      attrs["diagnostics"] = py::list();
      raise(g_scene_error, e.what(), attrs);
    } catch (const UnreadableFile& e) {
      raise(g_unreadable, e.what());
    } catch (const Diverged& e) {
      py::dict attrs;
      attrs["time"] = e.time;
      attrs["step"] = e.step_index;
      raise(g_diverged, e.what(), attrs);
    } catch (const io::IoError& e) {
      raise(g_output, e.what());
    }
  });
}

}  // namespace tumble::py_bind

PYBIND11_MODULE(_tumble, m) {
  namespace tb = tumble::py_bind;
  m.doc() = "tumble: free rigid bodies from particle clouds (simulate, mass properties, render, glTF)";
  m.attr("__version__") = TUMBLE_VERSION;
  tb::add_errors(m);
  tb::add_mass(m);
  tb::add_scene(m);
  tb::add_run(m);
  tb::add_render(m);
  m.def(
      "methods",
      [] {
        pybind11::list out;
        for (const tumble::MethodInfo& i : tumble::method_table()) {
          pybind11::dict d;
          d["name"] = std::string(i.name);
          d["description"] = std::string(i.description);
          d["order"] = i.order;
          d["adaptive"] = i.adaptive != nullptr;
          d["closed_form_if_free"] = i.closed_form_if_free;
          d["auto_candidate"] = i.auto_candidate;
          d["max_turn_per_step"] = i.max_turn_per_step;
          d["cost_ns_free"] = i.cost.free;
          d["cost_ns_forced"] = i.cost.forced;
          d["cost_ns_forced_axisymmetric"] = i.cost.forced_axisymmetric;
          out.append(d);
        }
        return out;
      },
      "The method table: one dict per method (name, description, order, adaptive, ..., cost_ns_free in ns/step).");
}
