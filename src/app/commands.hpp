// The subcommands of `tumble`. Each registers its options on the CLI11 app and,
// when chosen, sets `action` to the work to run after parsing.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include <CLI/CLI.hpp>

#include "base/format.hpp"
#include "io/trajectory_csv.hpp"
#include "scene/scene.hpp"

namespace tumble::render {
enum class GlBackend;
}

namespace tumble::app {

/// Exit codes (documented in scenes/README.md and the README).
enum ExitCode : int { kOk = 0, kRuntimeError = 1, kInputError = 2, kDiverged = 3 };

using Action = std::function<int()>;

/// A path option or argument: an empty string (an unset shell variable, say)
/// is refused, never taken as "the default" or "the current folder".
inline const CLI::Validator kPath{
    [](std::string& s) { return s.empty() ? std::string("expected a path, found an empty string") : std::string(); },
    "PATH"};

/// Registers subcommand `name`: its options in an `Options` shared with the
/// action, which runs `run` on them once the command line is parsed. A command
/// on a scene (one with Options::scene) takes the scene file first.
template <class Options>
std::pair<CLI::App*, std::shared_ptr<Options>> add_command(CLI::App& app, Action& action, const std::string& name,
                                                          const std::string& help, int (*run)(const Options&)) {
  auto o = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(name, help);
  if constexpr (requires { o->scene; }) cmd->add_option("scene", o->scene, "Scene file (TOML)")->required()->check(kPath);
  cmd->callback([o, run, &action] { action = [o, run] { return run(*o); }; });
  return {cmd, o};
}

void add_simulate_command(CLI::App& app, Action& action);
void add_info_command(CLI::App& app, Action& action);
void add_render_command(CLI::App& app, Action& action);
void add_assemble_command(CLI::App& app, Action& action);
void add_compare_command(CLI::App& app, Action& action);
void add_golden_command(CLI::App& app, Action& action);
/// Lists `bench` among the commands; run_bench_tool does the work.
void add_bench_command(CLI::App& app, Action& action);
/// `tumble bench ARGS`: replaces this process with tumble-bench ARGS from the
/// folder of this binary; returns an exit code only when it cannot.
int run_bench_tool(int argc, char** argv);
void add_methods_command(CLI::App& app, Action& action);
void add_export_command(CLI::App& app, Action& action);
void add_storyboard_command(CLI::App& app, Action& action);

/// The integration methods as a markdown table (`tumble methods --markdown`,
/// docs/methods.md), one row per row of core's method table: name, order, description.
std::string methods_markdown();

/// The options that are scene keys ([output] width, height, fps, aa, msaa),
/// shared by `render` and `storyboard`: they go into the scene before it is
/// validated, so the loader's checks cover them too.
struct FrameOverrides {
  std::optional<int> width, height, msaa;
  std::optional<double> fps;
  std::string aa;
};
std::vector<scene::Override> frame_overrides(const FrameOverrides& o);
/// `quality`: the command has --quality too (the help says --aa and --msaa override it).
void add_frame_override_options(CLI::App* cmd, FrameOverrides& o, bool quality);

/// The GL backend of `--gl` (or, when empty, of env TUMBLE_GL): an InputError
/// naming the option for an unknown name, so it fails before any work.
render::GlBackend parse_backend_option(const std::string& gl);

/// `--gl` and `--gpu` as render and storyboard take them: the backend (--gpu
/// implies egl; with --gl osmesa an InputError) and the EGL device (--gpu,
/// else env TUMBLE_EGL_DEVICE for egl, else automatic), checked before any work.
struct GlChoice {
  render::GlBackend backend;
  std::optional<int> gpu;
};
GlChoice choose_gl(const std::string& gl, std::optional<int> gpu);
void add_gl_options(CLI::App* cmd, std::string& gl, std::optional<int>& gpu);

/// Runs `action`, mapping exceptions to messages on stderr and exit codes.
int run_action(const Action& action);

/// load_scene (with command-line overrides) plus its warnings printed to stderr.
scene::Scene load_scene_verbose(const std::filesystem::path& path, const std::vector<scene::Override>& overrides = {});

}  // namespace tumble::app
