#include "app/mesh_info.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "app/commands.hpp"

namespace tumble::app {

namespace {

std::string vec(const Eigen::Vector3d& v) {
  return "[" + format_number(v.x()) + ", " + format_number(v.y()) + ", " + format_number(v.z()) + "]";
}

std::string yes_no(bool b) { return b ? "yes" : "no"; }

}  // namespace

std::string mesh_text(const scene::MeshSource& m) {
  const MeshReport& r = m.report;
  std::ostringstream o;
  o << "  mesh              " << m.file << " (fill " << m.fill << ", " << format_number(m.units, 4) << " m per file unit)\n"
    << "    triangles       " << r.triangles << " (" << r.vertices << " vertices), " << r.degenerate_faces
    << " degenerate\n"
    << "    watertight      " << yes_no(r.watertight()) << " (" << r.boundary_edges << " boundary, "
    << r.non_manifold_edges << " non-manifold, " << r.misoriented_edges << " misoriented edges)\n"
    << "    signed volume   " << format_number(r.signed_volume, 4) << " m^3 ("
    << (m.flipped ? "inside out: flipped" : r.signed_volume >= 0 ? "outward" : "inward") << "), area "
    << format_number(r.area, 4) << " m^2\n"
    << "    bounding box    " << vec(r.box_min) << " .. " << vec(r.box_max) << " m (file axes, scaled)\n";
  if (!m.inside_test.empty()) o << "    inside test     " << m.inside_test << "\n";
  o << "    particles       " << m.particles;
  if (m.spacing > 0) o << " (spacing " << format_number(m.spacing, 4) << " m)";
  o << ", mass " << format_number(m.mass, 4) << " kg\n";
  if (m.file_mass > 0) {
    o << "    masses          per vertex, the PLY's `mass` property (sum " << format_number(m.file_mass, 4) << " kg";
    if (std::abs(m.mass - m.file_mass) > 1e-12 * m.file_mass) o << ", scaled to the shape's " << format_number(m.mass, 4) << " kg";
    o << ")";
    if (m.massless_vertices > 0) o << "; " << m.massless_vertices << " vertices of mass 0 left out";
    o << "\n";
  }
  auto rows = [&](const char* label, const Eigen::Matrix3d& J) {
    o << "    " << label << vec(J.row(0).transpose()) << " kg m^2 (cloud axes, about its own centre of mass)\n";
    for (int i = 1; i < 3; ++i) o << "                    " << vec(J.row(i).transpose()) << "\n";
  };
  if (m.has_exact) rows(m.fill == "surface" ? "exact (shell)   " : "exact (solid)   ", m.exact_inertia);
  rows("particle cloud  ", m.cloud_inertia);
  if (m.has_exact) o << "    relative error  " << format_number(m.inertia_error(), 4) << " (Frobenius norm)\n";
  return o.str();
}

io::Json mesh_json(const scene::MeshSource& m) {
  const MeshReport& r = m.report;
  auto v3 = [](const Eigen::Vector3d& v) { return io::Json::array({v.x(), v.y(), v.z()}); };
  auto m3 = [&](const Eigen::Matrix3d& J) {
    return io::Json::array({v3(J.row(0).transpose()), v3(J.row(1).transpose()), v3(J.row(2).transpose())});
  };
  io::Json j{{"file", m.file},
             {"fill", m.fill},
             {"units_m", m.units},
             {"triangles", r.triangles},
             {"vertices", r.vertices},
             {"degenerate_faces", r.degenerate_faces},
             {"watertight", r.watertight()},
             {"boundary_edges", r.boundary_edges},
             {"non_manifold_edges", r.non_manifold_edges},
             {"misoriented_edges", r.misoriented_edges},
             {"signed_volume", r.signed_volume},
             {"flipped", m.flipped},
             {"area", r.area},
             {"box_min", v3(r.box_min)},
             {"box_max", v3(r.box_max)},
             {"particles", m.particles},
             {"spacing", m.spacing},
             {"mass", m.mass},
             {"cloud_inertia", m3(m.cloud_inertia)},
             {"file_mass", m.file_mass},
             {"massless_vertices", m.massless_vertices}};
  if (m.has_exact) {
    j["exact_inertia"] = m3(m.exact_inertia);
    j["relative_error"] = m.inertia_error();
  }
  return j;
}

}  // namespace tumble::app
