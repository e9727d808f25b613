#include "render/worker_threads.hpp"

#include <sched.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>

namespace tumble::render {
namespace fs = std::filesystem;
namespace {

std::optional<std::string> read_first_line(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  if (!in || !std::getline(in, line)) return std::nullopt;
  return line;
}

std::optional<double> number(std::string_view s) {
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end == s.data()) return std::nullopt;
  return v;
}

/// v2: "max 100000" (no limit) or "QUOTA PERIOD", in µs.
std::optional<double> v2_limit(const fs::path& dir) {
  const auto line = read_first_line(dir / "cpu.max");
  if (!line) return std::nullopt;
  std::istringstream in(*line);
  std::string quota, period;
  in >> quota >> period;
  const auto q = number(quota), p = number(period);
  if (!q || !p || *p <= 0) return std::nullopt;  // "max", or unreadable
  return *q / *p;
}

/// v1: cpu.cfs_quota_us (-1 = no limit) over cpu.cfs_period_us.
std::optional<double> v1_limit(const fs::path& dir) {
  const auto quota = read_first_line(dir / "cpu.cfs_quota_us");
  const auto period = read_first_line(dir / "cpu.cfs_period_us");
  if (!quota || !period) return std::nullopt;
  const auto q = number(*quota), p = number(*period);
  if (!q || !p || *q <= 0 || *p <= 0) return std::nullopt;
  return *q / *p;
}

/// The tightest limit from `dir` up to `root` (a parent's quota caps its
/// children). Inside a container the cgroup path often does not exist under
/// the namespaced mount, whose root is then the container's own cgroup.
template <class Limit>
std::optional<double> tightest(const fs::path& root, const std::string& cgroup_path, Limit limit) {
  fs::path dir = root / fs::path(cgroup_path).relative_path();
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) dir = root;
  std::optional<double> best;
  for (;;) {
    if (const auto l = limit(dir); l && (!best || *l < *best)) best = l;
    if (dir == root || !dir.has_relative_path() || dir.parent_path() == dir) break;
    dir = dir.parent_path();
  }
  return best;
}

void keep_min(std::optional<double>& best, std::optional<double> l) {
  if (l && (!best || *l < *best)) best = l;
}

}  // namespace

std::optional<double> cgroup_cpu_limit(const fs::path& proc_self_cgroup, const fs::path& cgroup_root) {
  std::ifstream in(proc_self_cgroup);
  std::optional<double> best;
  // Lines "ID:CONTROLLERS:PATH"; v2's is "0::PATH".
  for (std::string line; std::getline(in, line);) {
    const auto c1 = line.find(':'), c2 = line.find(':', c1 + 1);
    if (c1 == std::string::npos || c2 == std::string::npos) continue;
    const std::string controllers = line.substr(c1 + 1, c2 - c1 - 1), path = line.substr(c2 + 1);
    if (controllers.empty()) {  // v2: mounted at the root, or at unified/ beside v1 (hybrid)
      keep_min(best, tightest(cgroup_root, path, v2_limit));
      keep_min(best, tightest(cgroup_root / "unified", path, v2_limit));
      continue;
    }
    std::istringstream list(controllers);
    for (std::string name; std::getline(list, name, ',');) {
      if (name != "cpu") continue;
      keep_min(best, tightest(cgroup_root / controllers, path, v1_limit));  // e.g. "cpu,cpuacct"
      if (controllers != "cpu") keep_min(best, tightest(cgroup_root / "cpu", path, v1_limit));
    }
  }
  return best;
}

int usable_cores(int affinity_cpus, std::optional<double> quota) {
  int n = std::max(affinity_cpus, 1);
  if (quota && *quota > 0) n = std::min(n, static_cast<int>(std::ceil(*quota - 1e-9)));
  return std::max(n, 1);
}

int usable_cores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  int affinity = 0;
  if (::sched_getaffinity(0, sizeof set, &set) == 0) affinity = CPU_COUNT(&set);
  if (affinity <= 0) affinity = static_cast<int>(std::thread::hardware_concurrency());
  return usable_cores(affinity, cgroup_cpu_limit("/proc/self/cgroup", "/sys/fs/cgroup"));
}

int parse_jobs(std::string_view text, std::string_view what) {
  int v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || v < 1 || v > 1024)
    throw std::invalid_argument(std::string(what) + " = '" + std::string(text) +
                                "': expected a whole number of threads from 1 to 1024");
  return v;
}

int worker_threads(int requested) {
  if (requested > 0) return requested;
  if (const char* env = std::getenv("TUMBLE_JOBS"); env != nullptr && *env != '\0')
    return parse_jobs(env, "TUMBLE_JOBS");
  return usable_cores();
}

}  // namespace tumble::render
