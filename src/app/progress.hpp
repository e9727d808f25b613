// What the user sees of a pipeline (src/run): a one-line progress bar on a
// terminal (frame k/N, frames per second, ETA), the pipeline's notes on
// stderr, Ctrl-C / SIGTERM as stop requests, and its Outcome as an exit code.
#pragma once

#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>

#include "run/listener.hpp"

namespace tumble::app {

class Progress {
 public:
  /// `enabled` false (or stderr not a terminal when `only_tty`) makes it silent.
  Progress(long total, bool enabled, bool only_tty = true);
  void update(long done);
  void finish();

 private:
  long total_;
  bool on_;
  std::chrono::steady_clock::time_point start_, last_;
};

class StopSignals;

/// run::Listener on the terminal: notes as "tumble: <line>" on stderr, a
/// progress bar when `progress` (and stderr is a terminal), stop signals
/// caught from arm_stop() on.
class ConsoleListener : public run::Listener {
 public:
  explicit ConsoleListener(bool progress);
  ~ConsoleListener() override;
  void note(const std::string& line) override;
  void begin(long total, const std::string& what) override;
  void advance(long done) override;
  void end() override;
  void arm_stop() override;
  int stop() const override;

 private:
  bool progress_;
  std::optional<Progress> bar_;
  std::unique_ptr<StopSignals> stop_;
};

/// The exit code of an outcome (0, 1 failed, 3 diverged, 128 + signal);
/// prints a done outcome's summary on stdout.
int exit_code(const run::Outcome& o);

}  // namespace tumble::app
