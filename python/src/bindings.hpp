// Shared pieces of the `tumble` Python module (pybind11): numpy views and the
// registration functions of each part.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <string_view>

#include <Eigen/Core>

#include "scene/scene.hpp"

namespace tumble::py_bind {

namespace py = pybind11;

/// A read-only numpy view of `n` rows of `cols` doubles at `data` (row stride
/// `row_bytes`), kept alive by `owner`: no copy.
inline py::array_t<double> view(const double* data, std::size_t n, std::size_t cols, std::size_t row_bytes,
                                py::handle owner) {
  std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(n)}, strides{static_cast<py::ssize_t>(row_bytes)};
  if (cols > 0) {
    shape.push_back(static_cast<py::ssize_t>(cols));
    strides.push_back(sizeof(double));
  }
  py::array_t<double> a(shape, strides, data, owner);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

/// Small fixed-size values are copied (they are a few doubles).
inline py::array_t<double> vec3(const Eigen::Vector3d& v) {
  py::array_t<double> a(3);
  for (int i = 0; i < 3; ++i) a.mutable_at(i) = v[i];
  return a;
}
inline py::array_t<double> mat3(const Eigen::Matrix3d& m) {
  py::array_t<double> a({3, 3});
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) a.mutable_at(i, j) = m(i, j);
  return a;
}
/// A 3-vector from any Python sequence of 3 numbers (ValueError otherwise).
Eigen::Vector3d to_vec3(const py::handle& h, const char* what);

/// A Python argument as an override of scene key `key`, read by the scene
/// loader as the command line's options are: its errors name it "tumble.call(arg=...)".
inline scene::Override arg_override(std::string_view call, std::string_view arg, std::string key,
                                    decltype(scene::Override::value) value) {
  return {"tumble." + std::string(call) + "(" + std::string(arg) + "=...)", std::move(key), std::move(value)};
}

/// warnings.warn(text, tumble.TumbleWarning), taking the GIL; raises (throws
/// py::error_already_set) where warnings are errors.
void warn(const std::string& text);

void add_errors(py::module_& m);
void add_mass(py::module_& m);
void add_scene(py::module_& m);
void add_run(py::module_& m);
void add_render(py::module_& m);

/// For long calls with the GIL released: raises KeyboardInterrupt (and any
/// other pending signal's exception) in C++ so the call unwinds and stops.
void check_signals();

}  // namespace tumble::py_bind
