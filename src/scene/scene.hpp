// A scene file (TOML) turned into ready-to-integrate bodies plus the render
// settings. Loading validates everything; errors name file:line:col and the key.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include <Eigen/Core>

#include "core/body.hpp"
#include "base/error.hpp"
#include "core/integrator.hpp"
#include "core/mass_properties.hpp"
#include "core/method_choice.hpp"
#include "core/particle_cloud.hpp"
#include "core/propagator.hpp"
#include "scene/explain.hpp"
#include "scene/frame_settings.hpp"
#include "core/solid_shape.hpp"
#include "viz/draw_options.hpp"
#include "core/triangle_mesh.hpp"

namespace tumble::scene {

struct Body;

/// Documented caps (scenes/README.md): beyond these a scene is rejected.
inline constexpr std::size_t kMaxParticles = 10'000'000;  ///< all bodies together
inline constexpr std::size_t kMaxBodies = 1000;
inline constexpr double kMaxFrames = 1e6;                 ///< duration × fps
// The step cap (duration / dt) is core's kMaxRunSteps.

/// The scene's [simulation]: core's StepConfig (method, dt, rtol, atol, with
/// core's defaults) plus what only a scene has.
struct SimulationConfig {
  StepConfig step;
  /// method = "auto": core picks each body's method (auto_without_tolerance,
  /// choose_method); step.method is then not read.
  bool automatic = false;
  double duration = 10;          ///< s
  double fps = 30;               ///< samples (frames) per second, 1/s
  /// "auto" only: largest end error (rad, see end_state_error); auto then picks dt too.
  std::optional<double> tolerance;
};

/// The config a body is stepped with when no measurement is needed: the scene's
/// step, or for "auto" core's pick without a tolerance.
StepConfig step_config(const SimulationConfig& sim, const RigidBodyModel& model);

/// How one body will be stepped, and why (`reason` is empty when the scene named the method).
struct MethodPlan {
  StepConfig config;
  std::string reason;
  std::vector<MethodEstimate> candidates;  ///< auto with a tolerance: every candidate measured
};
/// step_config, except that "auto" with a tolerance measures the candidates on
/// this body (choose_method) and picks the cheapest that meets it.
MethodPlan plan_method(const SimulationConfig& sim, const Body& body);
/// The step a config really takes, for people: "dt = 0.001 s", "rtol = 1e-08",
/// or "closed form" (`exact` on a torque-free body ignores dt).
std::string step_label(const StepConfig& c, const RigidBodyModel& m);

/// [output]: the frame settings (size, anti-aliasing, video) plus what only a scene sets.
struct OutputConfig : FrameSettings {
  double fps = 30;                              ///< frames per second (default: simulation.fps)
  Eigen::Vector3d background{0.97, 0.97, 0.98}; ///< linear RGB in [0, 1]
};

struct CameraConfig {
  bool automatic = true;                 ///< frame every body over the whole run
  Eigen::Vector3d position{4, -6, 3};    ///< m (used when !automatic)
  Eigen::Vector3d target{0, 0, 0};       ///< m
  Eigen::Vector3d up{0, 0, 1};
  double fov_y_deg = 35;                 ///< vertical field of view, degrees
  std::string follow;                    ///< body name; empty = fixed camera
  /// across = "L" (+1) or "-L" (−1): look across the first body's (or the
  /// followed body's) angular momentum, L up (or down) in the picture plane,
  /// from `azimuth` around L and `elevation` towards it (degrees); 0: not.
  int across = 0;
  double azimuth_deg = 25, elevation_deg = 12;
  /// With `across`: degrees L is turned clockwise in the picture from up (90: L
  /// points right, so a long L lies along a wide view).
  double roll_deg = 0;
};

/// `[draw]`: viz's options for the bodies (box, axes, particles, L, ω,
/// trails, grid: filled by name by the reader) plus the frame's text.
struct DrawConfig : viz::DrawOptions {
  bool overlay = true, legend = true;
  OverlayItems overlay_items;            ///< which parts of the overlay line (overlay = true)
};

/// [compare] arrange: where a comparison's cells stand beside its plots.
/// row: in one row above the highest plot; side: in one row in the band left
/// of the leftmost plot, the views' whole height (tall cells, larger bodies).
enum class CompareArrange { row, side };
inline constexpr std::pair<CompareArrange, const char*> kCompareArranges[] = {{CompareArrange::row, "row"},
                                                                             {CompareArrange::side, "side"}};

struct RenderConfig {
  OutputConfig output;
  CameraConfig camera;
  DrawConfig draw;
  std::vector<Method> compare_methods;   ///< [compare] methods; empty = no comparison
  std::vector<Method> compare_cells;     ///< [compare] cells: the methods drawn in a cell (others only plotted); empty = all
  /// [compare] steps: a method's own dt (s), e.g. Euler at a quarter of RK4's step for the same
  /// number of derivative evaluations; a method not listed takes [simulation] dt.
  std::vector<std::pair<Method, double>> compare_steps;
  CompareArrange compare_arrange = CompareArrange::row;  ///< [compare] arrange
  ExplainConfig explain;                 ///< time_scale, slow motion, captions, title, views
};

/// One `shape = { type = "mesh" }` of a body, kept for `tumble info` and drawing.
struct MeshSource {
  std::string file;                 ///< path as resolved against the scene folder
  std::string fill;                 ///< "volume", "surface" or "vertices"
  double units = 1;                 ///< m per file unit
  MeshReport report;                ///< in m, as read (before the orientation fix)
  bool flipped = false;             ///< was inside out; turned right way out
  std::string inside_test;          ///< volume fill: how inside was decided
  std::size_t ambiguous = 0;        ///< volume fill: lattice points with winding number in (0.25, 0.75)
  std::size_t near = 0;             ///< volume fill: lattice points with winding number over 0.25
  std::size_t overlapped = 0;       ///< volume fill: lattice points enclosed twice or negatively (self-intersection)
  TriangleMesh surface;             ///< body cloud axes (part placement applied), m
  double mass = 0;                  ///< kg
  std::size_t particles = 0;
  double spacing = 0;               ///< m between lattice points or samples
  double file_mass = 0;             ///< kg: sum of a PLY's per-vertex `mass` (fill "vertices"); 0 for equal masses
  std::size_t massless_vertices = 0;  ///< PLY vertices of mass 0, left out of the cloud
  bool has_exact = false;           ///< exact tensor known (watertight volume, or surface shell)
  Eigen::Vector3d exact_com = Eigen::Vector3d::Zero();      ///< cloud axes, m
  Eigen::Matrix3d exact_inertia = Eigen::Matrix3d::Zero();  ///< about exact_com, cloud axes, kg·m²
  Eigen::Vector3d cloud_com = Eigen::Vector3d::Zero();      ///< of its particles, m
  Eigen::Matrix3d cloud_inertia = Eigen::Matrix3d::Zero();  ///< of its particles about cloud_com, kg·m²
  Eigen::Vector3d color{0.3, 0.5, 0.8};                     ///< linear RGB (part colour, else the body's)

  /// ‖J_cloud − J_exact‖_F / ‖J_exact‖_F (what inertia_tolerance bounds).
  double inertia_error() const { return (cloud_inertia - exact_inertia).norm() / exact_inertia.norm(); }
};

/// One generated shape of a body (`shape = { type = "box", ... }`), drawn as
/// its lit surface at the declared dimensions.
struct ShapeSource {
  SolidShape shape;                 ///< placed in the body's cloud axes
  Eigen::Vector3d color{0.3, 0.5, 0.8};  ///< linear RGB (part colour, else the body's)
};

/// Particles [begin, end) of a body drawn in `color` (a part's colour).
struct ColorSpan {
  std::size_t begin = 0, end = 0;
  Eigen::Vector3d color;            ///< linear RGB in [0, 1]
};

struct Body {
  std::string name;                      ///< identifier (views, captions, CSV)
  std::string label;                     ///< what labels and keys show: display_name, else name
  ParticleCloud cloud;                   ///< cloud axes, as written in the scene
  MassProperties mass_properties;        ///< in cloud axes
  RigidBodyModel model;                  ///< what Propagator integrates (keep the Scene alive)
  InitialConditions initial_conditions;  ///< as written (orientation normalised)
  BodyState initial;                     ///< make_state(model, initial_conditions)
  Eigen::Vector3d color{0.3, 0.5, 0.8};  ///< linear RGB in [0, 1]
  std::vector<MeshSource> meshes;        ///< mesh shapes, drawn as surfaces
  std::vector<ShapeSource> shapes;       ///< generated shapes, drawn as surfaces
  std::vector<ColorSpan> part_colors;    ///< parts with their own colour
};

struct Scene {
  std::string name;
  std::filesystem::path path;            ///< as given to load_scene (empty for strings)
  std::string content_hash;              ///< FNV-1a 64 of the file bytes, 16 hex digits
  SimulationConfig simulation;
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();  ///< m/s², world
  bool has_gravity = false;
  std::vector<Body> bodies;
  RenderConfig render;
  std::vector<std::string> warnings;     ///< "file:line:col: warning: ..." lines

  const Body* find_body(std::string_view body_name) const;
};

/// One problem found while loading, located in the scene file.
struct Diagnostic {
  std::string file;
  std::string option;   ///< the command-line option that set the value ("--fps"), if one did
  int line = 0, column = 0;
  std::string key;      ///< e.g. "bodies[0].shape.size"; empty for syntax errors
  std::string message;  ///< what was expected and what was found
  /// "file:line:col: error: key: message", "--option: error: key: message",
  /// or "file: error: key: message" for a document built in code (line 0).
  std::string str() const;
};

/// All errors of one load, reported together. An InputError, so exit code 2.
class SceneError : public InputError {
 public:
  explicit SceneError(std::vector<Diagnostic> diags);
  const std::vector<Diagnostic>& diagnostics() const { return diags_; }

 private:
  std::vector<Diagnostic> diags_;
};

/// A command-line option that replaces (or, with no value, removes) a scene
/// key before validation, so it is checked by the same code as the file and
/// its errors name the option. `key` is a dotted path: "output.width".
struct Override {
  std::string option;  ///< as the user typed it: "--width"
  std::string key;
  std::variant<std::monostate, long long, double, std::string> value;
};

/// Largest scene file read, bytes (checked before reading).
inline constexpr std::size_t kMaxSceneBytes = std::size_t{256} << 20;

/// Reads and validates a scene; cloud files resolve relative to its folder.
/// Only a regular file is read (base/input_file.hpp). Throws SceneError (every
/// problem found), InputError (no such file) or UnreadableFile (a directory,
/// a device, a FIFO, permission denied). `content_hash` covers the file
/// only; the overrides show in the validated values.
Scene load_scene(const std::filesystem::path& path, const std::vector<Override>& overrides = {});

/// Same from text; `source_name` labels errors, `base_dir` resolves cloud files.
Scene load_scene_from_string(std::string_view text, std::string_view source_name,
                             const std::filesystem::path& base_dir = {},
                             const std::vector<Override>& overrides = {});

/// A scene's [simulation] and [output] settings (and output's time_scale).
struct Settings {
  SimulationConfig simulation;
  OutputConfig output;
  double time_scale = 1;
  std::vector<std::string> warnings;
  void apply_to(Scene& s) const;
};

/// The settings of a loaded (perhaps edited) scene with `overrides` applied
/// to them, as load_scene applies a command line's: the scene's values and the
/// overrides are written into [simulation] and [output] tables and read by the
/// loader's own code, so every check and message is the command line's, and
/// each error names its override's option (others name `source_name`, with no
/// position). Only "simulation.*" and "output.*" keys. Throws SceneError.
Settings override_settings(const Scene& s, const std::vector<Override>& overrides, std::string_view source_name);

/// Sample times k/fps for k = 0, 1, … up to `duration`; the last is always
/// exactly `duration` (appended when it is not a multiple of 1/fps).
std::vector<double> sample_times(double duration, double fps);

/// FNV-1a 64-bit hash of `bytes` as 16 lowercase hex digits.
std::string fnv1a_hex(std::string_view bytes);

}  // namespace tumble::scene
