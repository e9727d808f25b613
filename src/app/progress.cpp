#include "app/progress.hpp"

#include <unistd.h>

#include <iostream>

#include "app/commands.hpp"
#include "app/stop_signals.hpp"

namespace tumble::app {

Progress::Progress(long total, bool enabled, bool only_tty)
    : total_(total), on_(enabled && (!only_tty || ::isatty(STDERR_FILENO))),
      start_(std::chrono::steady_clock::now()), last_(start_) {}

void Progress::update(long done) {
  if (!on_) return;
  const auto now = std::chrono::steady_clock::now();
  // Redraw at most 10 times per second: the terminal is not free either.
  if (done < total_ && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  const double secs = std::chrono::duration<double>(now - start_).count();
  const double fps = secs > 0 ? done / secs : 0;
  const double eta = fps > 0 ? (total_ - done) / fps : 0;
  const int width = 30;
  const int filled = total_ > 0 ? static_cast<int>(width * done / total_) : width;
  std::fprintf(stderr, "\r[%-*.*s] frame %ld/%ld  %.1f frames/s  ETA %d:%02d ", width, filled,
               "##############################", done, total_, fps, static_cast<int>(eta) / 60,
               static_cast<int>(eta) % 60);
  std::fflush(stderr);
}

void Progress::finish() {
  if (on_) std::fprintf(stderr, "\n");
}

}  // namespace tumble::app

namespace tumble::app {

ConsoleListener::ConsoleListener(bool progress) : progress_(progress) {}
ConsoleListener::~ConsoleListener() = default;

void ConsoleListener::note(const std::string& line) { std::cerr << "tumble: " << line << "\n"; }

void ConsoleListener::begin(long total, const std::string& what) {
  if (progress_ && !what.empty()) note(what);
  bar_.emplace(total, progress_);
}

void ConsoleListener::advance(long done) {
  if (bar_) bar_->update(done);
}

void ConsoleListener::end() {
  if (bar_) bar_->finish();
  bar_.reset();
}

void ConsoleListener::arm_stop() {
  if (!stop_) stop_ = std::make_unique<StopSignals>();
}

int ConsoleListener::stop() const { return stop_ ? stop_->received() : 0; }

int exit_code(const run::Outcome& o) {
  switch (o.kind) {
    case run::Outcome::done: std::cout << o.summary << "\n"; return kOk;
    case run::Outcome::failed: return kRuntimeError;
    case run::Outcome::diverged: return kDiverged;
    case run::Outcome::interrupted: return 128 + o.signal;
  }
  return kRuntimeError;
}

}  // namespace tumble::app
