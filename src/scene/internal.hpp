// Pieces of the loader shared between its source files.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "base/quote.hpp"
#include "core/particle_cloud.hpp"
#include "scene/reader.hpp"
#include "scene/scene.hpp"

namespace tumble::scene::detail {

struct LoadContext {
  Diagnostics& diag;
  std::filesystem::path base_dir;  ///< cloud files resolve against it
  std::size_t particles = 0;       ///< running total, capped at kMaxParticles
  std::vector<std::string> body_names;  ///< every name seen, for the uniqueness check
  std::vector<MeshSource>* meshes = nullptr;  ///< where mesh shapes of the current source go
  std::vector<ShapeSource>* shapes = nullptr;  ///< where generated shapes of the current source go
};

/// Reserves `n` particles of the scene budget; false (with an error under `key`) past the cap.
bool reserve_particles(LoadContext& ctx, TableReader& r, std::string_view key, double n);

/// A `shape = { type = "mesh", ... }` table at `path`: appends its particles to
/// `out` (shifted by `offset`, m) and its MeshSource to ctx.meshes.
void read_mesh_shape(const toml::table& t, const std::string& path, LoadContext& ctx, const Eigen::Vector3d& offset,
                     ParticleCloud& out);

/// Appends the particles of every source in `r` (particles, shape, cloud) shifted
/// by `offset`; returns how many sources the table had.
int read_cloud_sources(TableReader& r, LoadContext& ctx, const Eigen::Vector3d& offset, ParticleCloud& out);

/// Reads [[bodies]] into scene.bodies (uses scene.gravity for the force sets).
void read_bodies(TableReader& root, LoadContext& ctx, Scene& scene);

/// Reads [output] into scene.render.output (and its time_scale).
void read_output_config(TableReader& root, LoadContext& ctx, Scene& scene);

/// Reads [output], [camera], [draw], [compare] into scene.render.
void read_render_config(TableReader& root, LoadContext& ctx, Scene& scene);

/// `across` of a camera table: "L" → +1, "-L" → −1 (an error otherwise, 0).
int read_across(TableReader& r);

/// `key` as simulated seconds or an event time of body `body` ("flip 1 - 0.2"),
/// clamped to [0, duration]; `written` gets the text as the file has it (explain_config.cpp).
std::optional<double> read_time(TableReader& r, std::string_view key, const Scene& s, std::size_t body,
                                std::string* written = nullptr);

/// A momentum_sphere view's `turn` and `build_up` (sphere_motion.cpp); errors for other kinds.
void read_turn(TableReader& r, LoadContext& ctx, const Scene& s, std::size_t body, ViewConfig& v);
void read_build_up(TableReader& r, const Scene& s, std::size_t body, ViewConfig& v);
void read_sphere_marks(TableReader& r, ViewConfig& v);
/// A momentum_sphere's `paths_of`: bodies whose Π it draws, each scaled to the sphere (sphere_marks.cpp).
void read_sphere_paths(TableReader& r, const LoadContext& ctx, ViewConfig& v);

/// A view's look (view_look.cpp): a world view's trail_axes, box, line_scale, tip_names;
/// a momentum_sphere's energy_ellipsoid, path, line_scale, levels.
void read_sphere_options(TableReader& r, ViewConfig& v);

/// A list of overlay items ("time", "state", "angle", ...) under `key`; none where `key` is no array (overlay_items.cpp).
std::optional<OverlayItems> read_overlay_items(TableReader& r, std::string_view key);
/// A world view's `readout` (of its own body) and `until`; errors for other kinds (overlay_items.cpp).
void read_view_readout(TableReader& r, const Scene& s, std::size_t body, ViewConfig& v);

/// Reads [[views]], [[captions]], [title], [[slow_motion]] into scene.render.explain
/// (after read_render_config and read_bodies: it checks body names and times).
void read_explain_config(TableReader& root, LoadContext& ctx, Scene& scene);

/// Warnings (file:line:col) for captions up too briefly to be read at video
/// speed (under kSecondsPerWord a word) and for captions shown at once in one place.
void check_pacing(TableReader& root, LoadContext& ctx, const Scene& scene);

}  // namespace tumble::scene::detail
