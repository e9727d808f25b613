#include "io/isolated.hpp"

#include <fcntl.h>
#include <sys/prctl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <new>

#include "base/error.hpp"

#ifdef TUMBLE_NO_ADDRESS_LIMIT
#include <sanitizer/common_interface_defs.h>
#endif


namespace tumble::io {

namespace {

void write_all(int fd, const std::string& s) {
  for (std::size_t off = 0; off < s.size();) {
    const ssize_t n = ::write(fd, s.data() + off, s.size() - off);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    off += static_cast<std::size_t>(n);
  }
}

// The child dies by its own signal, not in a handler inherited from the host
// (a fuzzer's or a crash reporter's would report the importer's crash as the host's).
void default_crash_signals() {
  for (const int sig : {SIGABRT, SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGTRAP, SIGXCPU, SIGXFSZ, SIGSYS})
    ::signal(sig, SIG_DFL);
}

// In the child: limits, the work, one tagged reply ('O' result, 'E' message, 'M' memory), _exit.
[[noreturn]] void child(int fd, const std::function<std::string()>& work, const IsolationLimits& limits) {
  default_crash_signals();
#ifdef TUMBLE_NO_ADDRESS_LIMIT
  // Likewise a sanitizer's report in the child (the importer's heap error) ends
  // the child only: a host's death callback (a fuzzer's) would file the host's input as a crash.
  __sanitizer_set_death_callback(nullptr);
#endif
  const auto cpu = static_cast<rlim_t>(std::ceil(limits.seconds)) + 1;
  const rlimit cpu_limit{cpu, cpu + 1};
  ::setrlimit(RLIMIT_CPU, &cpu_limit);
  if (kImportAddressLimit) {
    long pages = 0;  // the budget is on top of what the parent already maps
    if (std::FILE* f = std::fopen("/proc/self/statm", "r")) {
      if (std::fscanf(f, "%ld", &pages) != 1) pages = 0;
      std::fclose(f);
    }
    const auto as = static_cast<rlim_t>(pages) * static_cast<rlim_t>(::sysconf(_SC_PAGESIZE)) + limits.bytes;
    const rlimit as_limit{as, as};
    ::setrlimit(RLIMIT_AS, &as_limit);
  }
  std::string reply;
  try {
    reply = "O" + work();
  } catch (const InputError& e) {
    reply = std::string("E") + e.what();
  } catch (const std::bad_alloc&) {
    reply = "M";
  } catch (const std::exception& e) {
    reply = std::string("E") + e.what();
  }
  write_all(fd, reply);
  ::_exit(0);  // no atexit handlers, no static destructors: they belong to the parent
}

}  // namespace

std::string run_isolated(const std::function<std::string()>& work, const IsolationLimits& limits,
                         const std::string& what) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw InputError(what + ": cannot create a pipe: " + std::strerror(errno));
  std::fflush(nullptr);  // the child must not write the parent's buffered output twice
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]), ::close(fds[1]);
    throw InputError(what + ": cannot fork the guarded import: " + std::strerror(errno));
  }
  if (pid == 0) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // dies with its parent
    ::close(fds[0]);
    child(fds[1], work, limits);
  }
  ::close(fds[1]);
  std::string reply;
  bool timed_out = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(limits.seconds);
  char buf[1 << 16];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      timed_out = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int r = ::poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
    if (r < 0 && errno != EINTR) break;
    if (r <= 0) continue;
    const ssize_t n = ::read(fds[0], buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    reply.append(buf, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  if (timed_out) ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  char limit[64];
  std::snprintf(limit, sizeof limit, "%g s", limits.seconds);
  if (timed_out) throw InputError(what + ": took longer than " + std::string(limit) + " (the import time limit); refused");
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    if (sig == SIGXCPU) throw InputError(what + ": used more than " + std::string(limit) + " of CPU (the import time limit); refused");
    throw InputError(what + ": the importer crashed on this file (signal " + std::to_string(sig) + ", " +
                     strsignal(sig) + "); refused");
  }
  if (reply.empty()) throw InputError(what + ": the importer exited without a result (status " + std::to_string(WEXITSTATUS(status)) + ")");
  if (reply[0] == 'M')
    throw InputError(what + ": the import needs more than " + std::to_string(limits.bytes >> 20) +
                     " MiB (the import memory limit); refused");
  if (reply[0] == 'E') throw InputError(reply.substr(1));
  return reply.substr(1);
}

}  // namespace tumble::io
