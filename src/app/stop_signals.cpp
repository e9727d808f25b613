#include "app/stop_signals.hpp"

#include <atomic>

namespace tumble::app {

namespace {
// The one piece of global mutable state in the program, and the accepted
// exception: the number of the first SIGINT/SIGTERM received (0 = none). A
// lock-free atomic, because a signal handler may store to it and the frame
// workers read it from other threads (a volatile sig_atomic_t is only safe
// within one thread).
std::atomic<int> g_stop_signal{0};
static_assert(std::atomic<int>::is_always_lock_free, "a signal handler may only touch lock-free atomics");

extern "C" void on_stop_signal(int sig) { g_stop_signal.store(sig, std::memory_order_relaxed); }
}  // namespace

StopSignals::StopSignals() {
  g_stop_signal.store(0);
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESETHAND;
  ::sigaction(SIGINT, &sa, &old_int_);
  ::sigaction(SIGTERM, &sa, &old_term_);
}

StopSignals::~StopSignals() {
  ::sigaction(SIGINT, &old_int_, nullptr);
  ::sigaction(SIGTERM, &old_term_, nullptr);
}

int StopSignals::received() const { return g_stop_signal.load(std::memory_order_relaxed); }

}  // namespace tumble::app
