// A one-line progress bar on a terminal: frame k/N, frames per second, ETA.
#pragma once

#include <chrono>
#include <cstdio>

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

}  // namespace tumble::app
