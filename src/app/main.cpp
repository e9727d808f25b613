// tumble: simulate free rigid bodies given as particle clouds.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <csignal>
#include <iostream>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "scene/reader.hpp"

int main(int argc, char** argv) {
  // Past a file-size limit (ulimit -f) a write fails with EFBIG instead of
  // killing us with SIGXFSZ: the error is reported and the temp file removed.
  // Children (ffmpeg) inherit the ignored signal and fail the same way.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{"tumble: free rigid bodies from particle clouds", "tumble"};
  app.set_version_flag("--version", "tumble " TUMBLE_VERSION);
  app.require_subcommand(1);
  tumble::app::Action action;
  tumble::app::add_simulate_command(app, action);
  tumble::app::add_info_command(app, action);
#ifdef TUMBLE_HAVE_RENDER
  tumble::app::add_render_command(app, action);
  tumble::app::add_assemble_command(app, action);
  tumble::app::add_compare_command(app, action);
  tumble::app::add_golden_command(app, action);
  tumble::app::add_storyboard_command(app, action);
#endif
  tumble::app::add_bench_command(app, action);
  tumble::app::add_methods_command(app, action);
  tumble::app::add_export_command(app, action);
  if (argc >= 2 && std::string(argv[1]) == "bench") return tumble::app::run_bench_tool(argc - 2, argv + 2);
  if (argc < 2) {  // no command: say what there is
    std::cout << app.help();
    return tumble::app::kOk;
  }
  if (const std::string first = argv[1]; !first.empty() && first[0] != '-') {
    std::vector<std::string> names;
    for (const CLI::App* sub : app.get_subcommands({})) names.push_back(sub->get_name());
    if (std::find(names.begin(), names.end(), first) == names.end()) {
      const std::vector<std::string_view> views(names.begin(), names.end());
      const std::string hint = tumble::scene::detail::closest(first, views);
      std::cerr << "tumble: unknown command '" << first << "'"
                << (hint.empty() ? std::string() : "; did you mean '" + hint + "'?") << "\ncommands:";
      for (const std::string& n : names) std::cerr << " " << n;
      std::cerr << "\nRun with --help for more information.\n";
      return tumble::app::kInputError;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : tumble::app::kInputError;  // usage errors are input errors
  }
  return tumble::app::run_action(action);
}
