// `tumble export SCENE --gltf out.glb|.gltf [--fps N]`: the simulated scene as glTF.
#include <iostream>
#include <memory>
#include <string>

#include "app/commands.hpp"
#include "core/format.hpp"
#include "io/atomic_file.hpp"
#ifdef TUMBLE_HAVE_GLTF
#include "gltf/gltf_export.hpp"
#endif

namespace tumble::app {

namespace {

struct ExportOptions {
  std::string scene, gltf;
  double fps = 0;
  CLI::Option* fps_opt = nullptr;
};

int run_export(const ExportOptions& o) {
#ifdef TUMBLE_HAVE_GLTF
  std::vector<scene::Override> overrides;  // --fps is the scene's output.fps, checked by the loader
  if (o.fps_opt->count()) overrides.push_back({"--fps", "output.fps", o.fps});
  const scene::Scene s = load_scene_verbose(o.scene, overrides);
  io::check_output_file("--gltf", o.gltf);  // after the load, so the scene and its meshes count as inputs
  const std::vector<scene::Trajectory> tracks = gltf::export_gltf(s, o.gltf, 0, "--gltf");
  std::cerr << "tumble: wrote " << o.gltf << ": " << tracks.size() << " bodies, "
            << (tracks.empty() ? 0 : tracks[0].size()) << " keyframes at " << format_number(s.render.output.fps, kShortestDigits)
            << " fps\n";
  return kOk;
#else
  (void)o;
  std::cerr << "tumble: this build has no glTF export (install libtinygltf-dev and rebuild)\n";
  return kRuntimeError;
#endif
}

}  // namespace

void add_export_command(CLI::App& app, Action& action) {
  const auto [cmd, o] = add_command(app, action, "export",
                                    "Simulate a scene and write it as glTF 2.0 "
                                    "(bodies, keyframes, principal axes)", run_export);
  cmd->add_option("--gltf", o->gltf, "Output file: .glb (binary) or .gltf (JSON, buffer embedded)")->required()->check(kPath);
  o->fps_opt = cmd->add_option("--fps", o->fps, "Keyframes per second (default: the scene's output fps)");
}

}  // namespace tumble::app
