// `tumble bench ARGS` runs tumble-bench ARGS (src/bench), found beside this
// binary: the user's `tumble` carries no benchmark, study or peer code, and a
// build without them says how to get them instead of failing obscurely.
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <system_error>
#include <vector>

#include "app/commands.hpp"

namespace tumble::app {

namespace fs = std::filesystem;

void add_bench_command(CLI::App& app, Action&) {
  // Listed in --help and known to the misspelling hint; main() hands the
  // command line over before CLI11 parses it.
  app.add_subcommand("bench", "Work-precision, convergence, stability and drift of every method (+ peers): runs tumble-bench")
      ->allow_extras();
}

int run_bench_tool(int argc, char** argv) {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  const fs::path tool = ec ? fs::path() : self.parent_path() / "tumble-bench";
  if (tool.empty() || ::access(tool.c_str(), X_OK) != 0) {
    std::cerr << "tumble bench: the benchmark tool is not built"
              << (tool.empty() ? std::string() : " (no executable " + tool.string() + ")")
              << "; configure with -DTUMBLE_BUILD_BENCH=ON (Debian: libbenchmark-dev) and build the target "
                 "tumble-bench, or run scripts/test.sh\n";
    return kInputError;
  }
  std::vector<char*> args{const_cast<char*>(tool.c_str())};
  for (int i = 0; i < argc; ++i) args.push_back(argv[i]);
  args.push_back(nullptr);
  std::cout.flush();
  ::execv(tool.c_str(), args.data());
  std::cerr << "tumble bench: cannot run " << tool.string() << ": " << std::strerror(errno) << "\n";
  return kRuntimeError;
}

}  // namespace tumble::app
