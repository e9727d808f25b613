// What is drawn of a body besides its box and axes, prepared once per body:
// its mesh surfaces and the particles that can be seen (GL-free).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "core/particle_cloud.hpp"
#include "core/triangle_mesh.hpp"
#include "viz/draw_list.hpp"

namespace tumble::viz {

/// Indices of the particles on the outside of the cloud: those whose cell in a
/// grid of about the lattice spacing has an empty face neighbour. A cell at
/// least as wide as the spacing holds a lattice point, so interior cells are
/// never empty and interior particles (hidden behind the shell) are dropped.
std::vector<std::uint32_t> visible_particles(const ParticleCloud& cloud);

/// Flat-shaded triangle soup of a mesh in cloud axes (m), as a draw-list item shares it.
std::shared_ptr<const SurfaceMesh> make_surface(const TriangleMesh& mesh);

struct BodyLook {
  std::vector<std::shared_ptr<const SurfaceMesh>> surfaces;
  std::vector<Color> surface_colors;     ///< one per surface
  std::vector<std::uint32_t> visible;    ///< particles drawn
  std::vector<Color> particle_colors;    ///< one per entry of `visible`
};

}  // namespace tumble::viz
