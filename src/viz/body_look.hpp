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
/// grid of about the lattice spacing has an empty face neighbour (exposed_directions).
std::vector<std::uint32_t> visible_particles(const ParticleCloud& cloud);

/// Flat-shaded triangle soup of a mesh in cloud axes (m), as a draw-list item shares it.
std::shared_ptr<const SurfaceMesh> make_surface(const TriangleMesh& mesh);

struct BodyLook {
  std::vector<std::shared_ptr<const SurfaceMesh>> surfaces;
  std::vector<Color> surface_colors;     ///< one per surface
  std::shared_ptr<const ParticleSet> particles;  ///< null: particles not drawn
};

}  // namespace tumble::viz
