// Runs a third-party parser where it cannot hurt us: in a forked child with a
// wall-clock and CPU limit and an address-space budget, its result passed back
// through a pipe. An assert (SIGABRT), a crash, an endless loop or a runaway
// allocation in the parser becomes an InputError naming what happened, and the
// process goes on. (fork, not threads: only a separate process survives abort().)
#pragma once

#include <cstddef>
#include <functional>
#include <string>

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define TUMBLE_NO_ADDRESS_LIMIT 1  // sanitizers reserve terabytes of shadow address space
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define TUMBLE_NO_ADDRESS_LIMIT 1
#endif
#endif

namespace tumble::io {

#ifdef TUMBLE_NO_ADDRESS_LIMIT
inline constexpr bool kImportAddressLimit = false;
#else
inline constexpr bool kImportAddressLimit = true;  ///< whether IsolationLimits::bytes is applied (not under sanitizers)
#endif

struct IsolationLimits {
  double seconds = 60;                        ///< wall clock (and CPU, +1 s) for the child
  std::size_t bytes = std::size_t{4} << 30;   ///< address space the child may add (not under sanitizers)
};

/// `work()`'s result, computed in a child process. Throws InputError
/// "<what>: <why>" when the child throws InputError (its message), runs out of
/// memory, exceeds the time, or dies on a signal.
std::string run_isolated(const std::function<std::string()>& work, const IsolationLimits& limits,
                         const std::string& what);

}  // namespace tumble::io
