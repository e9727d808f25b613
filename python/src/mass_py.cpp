// tumble.mass_properties (point masses) and tumble.mesh_properties (a mesh
// file, read and filled by the scene reader exactly as a scene's mesh shape).
#include <filesystem>
#include <optional>
#include <sstream>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#include "core/mass_properties.hpp"
#include "scene/scene.hpp"

namespace tumble::py_bind {

namespace {

/// What both functions return: the particle cloud's mass properties, and for
/// a mesh its report and exact (polyhedral) tensor.
struct Properties {
  MassProperties mp;
  std::size_t particles = 0;
  std::optional<scene::MeshSource> mesh;
};

ParticleCloud cloud_from(const py::array_t<double, py::array::c_style | py::array::forcecast>& points,
                         const py::array_t<double, py::array::c_style | py::array::forcecast>& masses) {
  const std::string call = "tumble.mass_properties(";
  if (points.ndim() != 2 || points.shape(1) != 3 || points.shape(0) == 0)
    throw InputError(call + "points=...): error: expected an (N, 3) array of positions (m), N >= 1");
  if (masses.ndim() != 1 || masses.shape(0) != points.shape(0))
    throw InputError(call + "masses=...): error: expected an (N,) array of masses (kg), N = len(points) = " +
                     std::to_string(points.shape(0)));
  ParticleCloud c(static_cast<std::size_t>(points.shape(0)));
  auto p = points.unchecked<2>();
  auto w = masses.unchecked<1>();
  for (py::ssize_t i = 0; i < points.shape(0); ++i) c[i] = {Eigen::Vector3d(p(i, 0), p(i, 1), p(i, 2)), w(i)};
  return c;
}

/// The arguments of mesh_properties as the keys of a one-body scene's mesh
/// shape, each an override that the scene loader reads and names on error.
std::vector<scene::Override> mesh_keys(const std::string& path, const std::string& units, std::optional<double> mass,
                                       std::optional<double> density, const std::string& fill,
                                       std::optional<int> resolution, std::optional<double> inertia_tolerance) {
  const std::string shape = "bodies[0].shape.";
  auto arg = [&](const char* name, decltype(scene::Override::value) v) {
    return arg_override("mesh_properties", name, shape + name, std::move(v));
  };
  std::vector<scene::Override> o{{"tumble.mesh_properties()", "bodies[0].name", std::string("mesh")},
                                 {"tumble.mesh_properties()", shape + "type", std::string("mesh")},
                                 arg_override("mesh_properties", "path", shape + "file", path), arg("units", units),
                                 arg("fill", fill)};
  if (mass) o.push_back(arg("mass", *mass));
  if (density) o.push_back(arg("density", *density));
  if (resolution) o.push_back(arg("resolution", static_cast<long long>(*resolution)));
  if (inertia_tolerance) o.push_back(arg("inertia_tolerance", *inertia_tolerance));
  return o;
}

/// The loader's errors about the call's own scene, told as the call's: each
/// names its argument, without the scene key or position the user never wrote.
[[noreturn]] void rethrow_as_call(const scene::SceneError& e) {
  std::vector<scene::Diagnostic> d = e.diagnostics();
  for (scene::Diagnostic& x : d) {
    if (!x.option.empty()) x.key.clear();
    x.line = x.column = 0;
    x.file = "tumble.mesh_properties()";
  }
  throw scene::SceneError(std::move(d));
}

}  // namespace

/// tumble.mass_properties and tumble.mesh_properties.
static void add_mass_functions(py::module_& m) {
  m.def(
      "mass_properties",
      [](const py::array_t<double, py::array::c_style | py::array::forcecast>& points,
         const py::array_t<double, py::array::c_style | py::array::forcecast>& masses) {
        const ParticleCloud c = cloud_from(points, masses);
        try {
          return Properties{compute_mass_properties(c, "points"), c.size(), std::nullopt};
        } catch (const InputError& e) {
          // Core words it for a scene's body: told here as the call's argument.
          std::string why = e.what();
          if (why.rfind("body 'points': ", 0) == 0) why.erase(0, 15);
          const bool mass = why.find(" has mass ") != std::string::npos || why.find("total mass") != std::string::npos;
          throw InputError(std::string("tumble.mass_properties(") + (mass ? "masses" : "points") + "=...): error: " + why);
        }
      },
      py::arg("points"), py::arg("masses"),
      "Mass properties of point masses: points (N, 3) in m, masses (N,) in kg (each finite and > 0). Errors "
      "(tumble.SceneError) name the argument.");

  m.def(
      "mesh_properties",
      [](const std::filesystem::path& path, const std::string& units, std::optional<double> mass,
         std::optional<double> density, const std::string& fill, std::optional<int> resolution,
         std::optional<double> inertia_tolerance) {
        std::error_code ec;
        if (!std::filesystem::exists(path, ec))
          throw InputError("tumble.mesh_properties(path=...): error: no such file: " + path.string() +
                           (path.is_relative() ? " (relative to the current folder, " +
                                                     std::filesystem::current_path(ec).string() + ")"
                                               : std::string()));
        const std::vector<scene::Override> keys = mesh_keys(std::filesystem::absolute(path).string(), units, mass,
                                                            density, fill, resolution, inertia_tolerance);
        scene::Scene s;
        try {
          py::gil_scoped_release nogil;  // a fine lattice takes a while
          s = scene::load_scene_from_string("", "tumble.mesh_properties()", {}, keys);
        } catch (const scene::SceneError& e) {
          rethrow_as_call(e);
        }
        for (const std::string& w : s.warnings) warn(w);
        scene::Body& b = s.bodies.at(0);
        return Properties{b.mass_properties, b.cloud.size(), b.meshes.at(0)};
      },
      py::arg("path"), py::kw_only(), py::arg("units") = "m", py::arg("mass") = py::none(),
      py::arg("density") = py::none(), py::arg("fill") = "volume", py::arg("resolution") = py::none(),
      py::arg("inertia_tolerance") = py::none(),
      "Mass properties of a mesh file filled as a scene's mesh shape (read and checked by the scene loader; errors "
      "name the argument): units 'm', 'cm', 'mm' or 'in'; mass= (kg) or density= (kg/m³, kg/m² for fill='surface'), "
      "not both (neither: 1 kg, as in a scene); fill 'volume', 'surface' or 'vertices'; resolution = lattice "
      "points along the longest edge, or inertia_tolerance = the coarsest lattice within it of the exact tensor. Returns the particle cloud's values and, where known, the exact tensor.");
}

void add_mass(py::module_& m) {
  py::class_<Properties>(m, "MassProperties",
                         "Mass (kg), centre of mass (m), inertia tensor about it (kg·m²) and principal moments "
                         "(ascending) and axes (columns, right-handed), in the input's axes; for a mesh also "
                         "the exact polyhedral values (exact_com, exact_inertia) and the mesh check.")
      .def_property_readonly("mass", [](const Properties& p) { return p.mp.mass; })
      .def_property_readonly("com", [](const Properties& p) { return vec3(p.mp.com); })
      .def_property_readonly("inertia", [](const Properties& p) { return mat3(p.mp.inertia); })
      .def_property_readonly("principal_moments", [](const Properties& p) { return vec3(p.mp.principal_moments); })
      .def_property_readonly("principal_axes", [](const Properties& p) { return mat3(p.mp.principal_axes); })
      .def_property_readonly("particles", [](const Properties& p) { return p.particles; })
      .def_property_readonly("has_exact", [](const Properties& p) { return p.mesh && p.mesh->has_exact; })
      .def_property_readonly("exact_com", [](const Properties& p) -> py::object {
        if (!p.mesh || !p.mesh->has_exact) return py::none();
        return vec3(p.mesh->exact_com);
      })
      .def_property_readonly("exact_inertia", [](const Properties& p) -> py::object {
        if (!p.mesh || !p.mesh->has_exact) return py::none();
        return mat3(p.mesh->exact_inertia);
      })
      .def_property_readonly("inertia_error", [](const Properties& p) -> py::object {
        if (!p.mesh || !p.mesh->has_exact) return py::none();
        return py::float_(p.mesh->inertia_error());
      })
      .def_property_readonly("mesh", [](const Properties& p) -> py::object {
        if (!p.mesh) return py::none();
        const scene::MeshSource& s = *p.mesh;
        py::dict d;
        d["file"] = s.file;
        d["fill"] = s.fill;
        d["units"] = s.units;
        d["triangles"] = s.report.triangles;
        d["vertices"] = s.report.vertices;
        d["watertight"] = s.report.watertight();
        d["volume"] = s.report.signed_volume;
        d["area"] = s.report.area;
        d["flipped"] = s.flipped;
        d["inside_test"] = s.inside_test;
        d["spacing"] = s.spacing;
        return py::object(std::move(d));
      })
      .def("__repr__", [](const Properties& p) {
        std::ostringstream o;
        o << "MassProperties(mass=" << p.mp.mass << " kg, principal_moments=[" << p.mp.principal_moments.transpose()
          << "] kg·m², particles=" << p.particles << ")";
        return o.str();
      });

  add_mass_functions(m);
}

}  // namespace tumble::py_bind
