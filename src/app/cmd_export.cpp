// `tumble export SCENE --gltf out.glb|.gltf [--fps N]`: the simulated scene as glTF.
#include <iostream>
#include <memory>
#include <string>

#include "app/commands.hpp"
#include "base/format.hpp"
#include "io/atomic_file.hpp"
#ifdef TUMBLE_HAVE_GLTF
#include "gltf/gltf_export.hpp"
#endif

namespace tumble::app {

namespace {

struct ExportOptions {
  std::string scene, gltf;
  double fps = 0;
  double key_tolerance = 0;
  CLI::Option *fps_opt = nullptr, *tolerance_opt = nullptr;
};

int run_export(const ExportOptions& o) {
#ifdef TUMBLE_HAVE_GLTF
  std::vector<scene::Override> overrides;  // --fps is the scene's output.fps, checked by the loader
  if (o.fps_opt->count()) overrides.push_back({"--fps", "output.fps", o.fps});
  const scene::Scene s = load_scene_verbose(o.scene, overrides);
  io::check_output_file("--gltf", o.gltf);  // after the load, so the scene and its meshes count as inputs
  gltf::KeyOptions keys;
  if (o.tolerance_opt->count()) keys.tolerance = o.key_tolerance;
  const std::vector<scene::Trajectory> tracks = gltf::export_gltf(s, o.gltf, keys, "--gltf");
  const std::size_t base = gltf::keyframe_times(s).size();
  std::size_t added = 0;
  for (const scene::Trajectory& t : tracks) added += t.size() - base;
  std::cerr << "tumble: wrote " << o.gltf << ": " << tracks.size() << " bodies, " << base << " keyframes at "
            << format_number(s.render.output.fps, kShortestDigits) << " fps";
  if (added > 0) std::cerr << " and " << added << " more where bodies turn or accelerate fast";
  std::cerr << " (within " << format_number(keys.tolerance, 3) << " rad between keys)\n";
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
  o->fps_opt = cmd->add_option("--fps", o->fps,
                               "Keyframes per second at least (default: the scene's output fps); more are added "
                               "where a body turns or accelerates fast");
  o->tolerance_opt = cmd->add_option("--key-tolerance", o->key_tolerance,
                                     "Largest rotation error between keys, rad (default 0.001; the centre of mass "
                                     "within this times the body's radius)");
}

}  // namespace tumble::app
