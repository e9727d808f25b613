// A body's drawable particles, prepared once (GL-free): the shell of the
// cloud with, per particle, the lattice directions it is seen through, plus
// coarser levels of detail. Frames share it, so the renderer uploads it once.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "core/particle_cloud.hpp"
#include "viz/draw_list.hpp"

namespace tumble::viz {

/// Bit 2a: the cloud's grid neighbour along +axis a is empty; bit 2a+1: along −axis a.
inline constexpr std::uint8_t kAllDirections = 0x3F;

/// A grid of cells `cell` (m, per axis) whose cell (0, 0, 0) starts at `lo`.
struct ShellGrid {
  glm::dvec3 lo{0};
  glm::dvec3 cell{1};
};

/// The grid for a cloud: on a lattice (at most 64 N nodes in the product of the
/// distinct coordinates per axis) one lattice point per cell, cells centred on
/// them; otherwise cubic cells about the spacing of a box-filling lattice of
/// N points (a thicker shell, still correct).
ShellGrid shell_grid(const std::vector<glm::dvec3>& positions);

/// Shell of a cloud: per particle the empty face-neighbour directions of its
/// cell, OR-ed over its 26 neighbour cells (so a staircase surface, whose normal
/// lies between grid axes, keeps the directions it is seen from). 0 = interior
/// (all six face neighbours occupied, so hidden behind the shell: a cell at
/// least as wide as the lattice spacing holds a lattice point, so interior cells are never empty).
std::vector<std::uint8_t> exposed_directions(const std::vector<glm::dvec3>& positions, const ShellGrid& grid);

/// Back-face rule: a particle at `p` (cloud axes, m) with exposure mask `exposed`
/// can be seen from `eye` (cloud axes) only if the eye lies in front of, or less than
/// `radius` behind, the plane through `p` normal to one of its exposed directions.
bool faces_eye(std::uint8_t exposed, const glm::vec3& p, const glm::vec3& eye, float radius);

/// Indices (into `level`) of the particles that pass faces_eye for `camera`, the level
/// being placed by `model` (cloud axes -> world, rigid). An orthographic camera's eye
/// is taken far back along its axis. Replaces the contents of `out`.
void facing_particles(const ParticleLevel& level, const glm::dmat4& model, const Camera& camera,
                      std::vector<std::uint32_t>& out);

/// Levels stop when a level would have fewer than this many particles or cells per axis.
inline constexpr std::size_t kMinLevelParticles = 256;
/// Level-of-detail rule: the finest level whose spheres project to at least this
/// many pixels of radius at the body's nearest point (smaller ones only alias).
inline constexpr double kMinParticleRadiusPx = 1.5;

/// Builds the levels of a cloud; `colors` one per particle; `radius` m (level 0).
std::shared_ptr<const ParticleSet> make_particle_set(const ParticleCloud& cloud, const std::vector<Color>& colors,
                                                     float radius);

/// Level of `set` to draw, placed by `model` (cloud axes -> world), seen by `camera`
/// in a viewport `viewport_height_px` high.
std::size_t particle_level(const ParticleSet& set, const glm::dmat4& model, const Camera& camera,
                           double viewport_height_px);

}  // namespace tumble::viz
