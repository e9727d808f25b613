// `tumble bench`: the method studies (src/bench), or with --render the frame
// throughput of the demo.
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>

#include "app/atomic_file.hpp"
#include "app/commands.hpp"
#include "bench/bench.hpp"
#ifdef TUMBLE_HAVE_RENDER
#include "app/render_bench.hpp"
#include "render/resource_dir.hpp"
#endif

namespace tumble::app {

namespace {
/// Creates `dir` (and parents) now, so an unwritable folder fails before minutes of work.
void check_output_folder(const std::string& option, const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw IoError(option + " " + dir.string() + ": cannot create the folder: " + ec.message());
  if (::access(dir.c_str(), W_OK) != 0)
    throw IoError(option + " " + dir.string() + ": cannot write in the folder: " + std::strerror(errno));
}

struct BenchCliOptions {
  bench::BenchOptions studies;
  bool render = false;
  long frames = 240;
  std::string scene;
};
}  // namespace

void add_bench_command(CLI::App& app, Action& action) {
  auto o = std::make_shared<BenchCliOptions>();
  CLI::App* cmd = app.add_subcommand("bench", "Work-precision, convergence, stability and drift of every method (+ peers)");
  cmd->add_flag("--quick", o->studies.quick, "Small sweeps and short timing batches (under a minute)");
  cmd->add_option("-o,--out", o->studies.out_dir, "Output folder for CSV, PNG and summary.md")->capture_default_str();
  cmd->add_flag("--render", o->render, "Measure frames/s of the demo render (1280x720, 4x MSAA) instead");
  cmd->add_option("--frames", o->frames, "With --render: how many frames")->capture_default_str();
  cmd->add_option("--scene", o->scene, "With --render: scene (default scenes/dzhanibekov.toml)");
  cmd->callback([o, &action] {
    action = [o]() -> int {
      check_output_folder("bench -o", o->studies.out_dir);
      if (!o->render) return bench::run(o->studies, std::cout);
#ifdef TUMBLE_HAVE_RENDER
      const std::filesystem::path scene =
          o->scene.empty() ? render::find_resource_dir() / "scenes" / "dzhanibekov.toml" : std::filesystem::path(o->scene);
      run_render_bench(scene, o->frames, o->studies.out_dir / "render", std::cout);
      return kOk;
#else
      throw InputError("this build has no renderer (TUMBLE_BUILD_RENDER=OFF)");
#endif
    };
  });
}

}  // namespace tumble::app
