// `tumble compare A.png B.png`: the golden-image comparison on two files.
// Exit 0 same (within the tolerance), 1 different (including different
// sizes), 2 bad input (unreadable file, bad option).
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>

#include "app/commands.hpp"
#include "base/error.hpp"
#include "golden/compare.hpp"
#include "io/atomic_file.hpp"
#include "io/png.hpp"

namespace tumble::app {

namespace {

struct CompareCliOptions {
  std::string a, b, diff;
  golden::CompareOptions cmp;
};

std::string box_text(const golden::Box& b) {
  if (b.empty()) return "none";
  return "(" + std::to_string(b.x0) + "," + std::to_string(b.y0) + ")-(" + std::to_string(b.x1) + "," +
         std::to_string(b.y1) + ") " + std::to_string(b.x1 - b.x0 + 1) + "x" + std::to_string(b.y1 - b.y0 + 1);
}

// --diff must not overwrite an input (the expected golden, say) and must be
// writable: both checked before any work, exit 2.
void check_diff_path(const CompareCliOptions& o) {
  namespace fs = std::filesystem;
  const fs::path d = o.diff;
  std::error_code ec;
  for (const std::string& in : {o.a, o.b})
    if (fs::equivalent(d, in, ec) || fs::weakly_canonical(d, ec) == fs::weakly_canonical(in, ec))
      throw InputError("--diff " + o.diff + ": is the input " + in + "; writing it would destroy that image; choose another path");
  try {  // the policy of every output (io/atomic_file.hpp): no input by identity, no special file
    io::check_output_target(d, "--diff");
  } catch (const io::IoError& e) {
    throw InputError(e.what());  // compare's bad options are exit 2
  }
  const fs::path dir = d.parent_path().empty() ? fs::path(".") : d.parent_path();
  const fs::path probe = dir / (".tumble-diff-probe-" + std::to_string(::getpid()));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) throw InputError("--diff " + o.diff + ": cannot write there: " + std::strerror(errno));
  ::close(fd);
  ::unlink(probe.c_str());
}

int run_compare(const CompareCliOptions& o) {
  golden::check_compare_options(o.cmp);
  io::Image a, b;
  try {  // read first (cheap), so the inputs are known to the output policy below
    a = io::read_png(o.a);
    b = io::read_png(o.b);
  } catch (const std::exception& e) {
    std::cerr << "tumble compare: " << e.what() << "\n";
    return kInputError;
  }
  if (!o.diff.empty()) check_diff_path(o);
  const golden::Comparison c = golden::compare_images(a, b, o.cmp);
  std::cout << (c.pass ? "same: " : "different: ") << c.summary << "\n";
  if (!c.size_mismatch) {
    std::printf("  fraction over %d:  %.6f (limit %g)%s\n", o.cmp.max_delta, c.fraction, o.cmp.max_fraction,
                c.fraction_ok ? "" : "  FAIL");
    std::printf("  largest region:    %ld px, box %s (limit %ld)%s\n", c.region, box_text(c.region_box).c_str(),
                o.cmp.max_region, c.region_ok ? "" : "  FAIL");
    std::printf("  worst %dx%d mean:  %.2f levels, box %s (limit %g)%s\n", o.cmp.window, o.cmp.window, c.window_mean,
                box_text(c.window_box).c_str(), o.cmp.max_window_mean, c.window_ok ? "" : "  FAIL");
    std::fflush(stdout);
  }
  if (!o.diff.empty() && !c.size_mismatch) {
    io::Image d = golden::amplified_difference(a, b);
    golden::outline_offenders(d, c);
    io::write_png_atomic(o.diff, d);
    std::cout << "difference x16 written to " << o.diff << " (largest region outlined in yellow, worst window in cyan)\n";
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
                      format_number(golden::CompareOptions{}.max_fraction, kShortestDigits) + ")");
  cmd->add_option("--max-region", c.max_region,
                  "Fail when a connected region of differing pixels is larger than this, px (default " +
                      std::to_string(golden::CompareOptions{}.max_region) + ")");
  cmd->add_option("--window", c.window,
                  "Side of the square window of the pooled mean difference, px (default " +
                      std::to_string(golden::CompareOptions{}.window) + ")");
  cmd->add_option("--max-window-mean", c.max_window_mean,
                  "Fail when the mean difference over some window exceeds this, levels 0..255 (default " +
                      format_number(golden::CompareOptions{}.max_window_mean, kShortestDigits) + ")");
}

void add_compare_command(CLI::App& app, Action& action) {
  const auto [cmd, o] = add_command(app, action, "compare",
                                    "Compare two PNGs as golden images (exit 0 same, "
                                    "1 different, 2 bad input)", run_compare);
  cmd->add_option("actual", o->a, "PNG (e.g. a new render)")->required()->check(kPath);
  cmd->add_option("expected", o->b, "PNG (e.g. the golden)")->required()->check(kPath);
  cmd->add_option("--diff", o->diff, "Write |actual - expected| x16 as a PNG")->check(kPath);
  add_golden_tolerance_options(cmd, o->cmp);
}

}  // namespace tumble::app
