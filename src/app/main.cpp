// tumble: simulate free rigid bodies given as particle clouds.
#include <CLI/CLI.hpp>

#include "app/commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{"tumble: free rigid bodies from particle clouds", "tumble"};
  app.set_version_flag("--version", "tumble " TUMBLE_VERSION);
  app.require_subcommand(1);
  tumble::app::Action action;
  tumble::app::add_simulate_command(app, action);
  tumble::app::add_info_command(app, action);
#ifdef TUMBLE_HAVE_RENDER
  tumble::app::add_render_command(app, action);
  tumble::app::add_compare_command(app, action);
  tumble::app::add_golden_command(app, action);
#endif
  tumble::app::add_bench_command(app, action);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : tumble::app::kInputError;  // usage errors are input errors
  }
  return tumble::app::run_action(action);
}
