#include "bench/cli.hpp"

#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>

#include "bench/bench.hpp"

namespace tumble::bench {

void add_bench_command(CLI::App& app) {
  auto opt = std::make_shared<BenchOptions>();
  CLI::App* sub = app.add_subcommand("bench", "Work-precision, stability and drift charts of every method (+ peers)");
  sub->add_flag("--quick", opt->quick, "Small sweeps and short timing batches (about a minute or less)");
  sub->add_option("-o,--out", opt->out_dir, "Output folder for CSV, PNG and summary.md")->capture_default_str();
  sub->callback([opt] {
    const int rc = run(*opt, std::cout);
    if (rc != 0) throw CLI::RuntimeError(rc);
  });
}

}  // namespace tumble::bench
