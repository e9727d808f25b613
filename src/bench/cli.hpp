// Registers `tumble bench [--quick] [-o DIR]` on a CLI11 app.
#pragma once

namespace CLI {
class App;
}

namespace tumble::bench {

/// Adds the `bench` subcommand; its callback runs bench::run and exits with its code.
void add_bench_command(CLI::App& app);

}  // namespace tumble::bench
