// `tumble compare A.png B.png`: the golden-image comparison on two files.
// Exit 0 same (within the tolerance), 1 different (including different
// sizes), 2 bad input (unreadable file, bad option).
#include <iostream>
#include <memory>

#include "app/commands.hpp"
#include "core/error.hpp"
#include "golden/compare.hpp"
#include "io/png.hpp"

namespace tumble::app {

namespace {

struct CompareCliOptions {
  std::string a, b, diff;
  golden::CompareOptions cmp;
};

void check_tolerance(const golden::CompareOptions& c) {
  if (c.max_delta < 0 || c.max_delta > 255) throw InputError("--max-delta: expected 0..255, found " + std::to_string(c.max_delta));
  if (!(c.max_fraction >= 0 && c.max_fraction <= 1))
    throw InputError("--max-fraction: expected a number in [0, 1], found " + format_double(c.max_fraction));
}

int run_compare(const CompareCliOptions& o) {
  check_tolerance(o.cmp);
  io::Image a, b;
  try {
    a = io::read_png(o.a);
    b = io::read_png(o.b);
  } catch (const std::exception& e) {
    std::cerr << "tumble compare: " << e.what() << "\n";
    return kInputError;
  }
  const golden::Comparison c = golden::compare_images(a, b, o.cmp);
  std::cout << (c.pass ? "same: " : "different: ") << c.summary << "\n";
  if (!o.diff.empty() && !c.size_mismatch) {
    io::write_png_atomic(o.diff, golden::amplified_difference(a, b));
    std::cout << "difference x16 written to " << o.diff << "\n";
  }
  return c.pass ? kOk : 1;
}

}  // namespace

void add_golden_tolerance_options(CLI::App* cmd, golden::CompareOptions& c) {
  cmd->add_option("--max-delta", c.max_delta,
                  "A pixel differs when its largest channel difference exceeds this (0..255, default " +
                      std::to_string(golden::CompareOptions{}.max_delta) + ")");
  cmd->add_option("--max-fraction", c.max_fraction,
                  "Fail when more than this fraction of pixels differ (default " +
                      format_short(golden::CompareOptions{}.max_fraction) + ")");
}

void check_golden_tolerance(const golden::CompareOptions& c) { check_tolerance(c); }

void add_compare_command(CLI::App& app, Action& action) {
  auto o = std::make_shared<CompareCliOptions>();
  CLI::App* cmd = app.add_subcommand("compare", "Compare two PNGs as golden images (exit 0 same, 1 different, 2 bad input)");
  cmd->add_option("actual", o->a, "PNG (e.g. a new render)")->required();
  cmd->add_option("expected", o->b, "PNG (e.g. the golden)")->required();
  cmd->add_option("--diff", o->diff, "Write |actual - expected| x16 as a PNG");
  add_golden_tolerance_options(cmd, o->cmp);
  cmd->callback([o, &action] { action = [o] { return run_compare(*o); }; });
}

}  // namespace tumble::app
