// Ctrl-C / SIGTERM as a request: the work in flight finishes, files stay whole.
#pragma once

#include <csignal>

namespace tumble::app {

/// While alive, SIGINT and SIGTERM ask the render loop (or an encode) to stop
/// after the frames in flight; received() returns the signal (0 = none). The
/// handler has no SA_RESTART, so a blocked write returns EINTR and sees it.
/// One-shot (SA_RESETHAND): a second Ctrl-C kills at once, which is still
/// safe because every file is written by temp file + rename.
class StopSignals {
 public:
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;
  int received() const;

 private:
  struct sigaction old_int_ {}, old_term_ {};
};

}  // namespace tumble::app
