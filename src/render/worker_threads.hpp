// How many threads the frame pipeline may keep busy: the cores this process
// may run on (its affinity mask, e.g. `taskset`), lowered to its cgroup CPU
// quota (containers, `docker --cpus`, systemd CPUQuota), not the machine's
// core count, which over-subscribes a limited container badly.
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>

namespace tumble::render {

/// The CPU quota, in CPUs, of the cgroup named in `proc_self_cgroup` (the
/// format of /proc/self/cgroup) under `cgroup_root` (where cgroupfs is
/// mounted): v2 `cpu.max` ("max 100000" or "150000 100000"), v1
/// `cpu.cfs_quota_us` / `cpu.cfs_period_us` (-1 = none). The tightest limit
/// of the cgroup and its ancestors; nullopt when none is set or readable.
std::optional<double> cgroup_cpu_limit(const std::filesystem::path& proc_self_cgroup,
                                       const std::filesystem::path& cgroup_root);

/// `affinity_cpus` lowered to `quota` rounded up (1.5 CPUs keep 2 threads
/// busy part of the time), at least 1.
int usable_cores(int affinity_cpus, std::optional<double> quota);

/// This process: sched_getaffinity's count and the quota of its cgroup.
int usable_cores();

/// Worker threads: `requested` when > 0 (--jobs N), else env TUMBLE_JOBS
/// when set, else usable_cores(). Throws std::invalid_argument naming
/// TUMBLE_JOBS when it is not a whole number from 1 to 1024.
int worker_threads(int requested = 0);

/// Parses a --jobs / TUMBLE_JOBS value: a whole number from 1 to 1024;
/// throws std::invalid_argument naming `what` otherwise.
int parse_jobs(std::string_view text, std::string_view what);

}  // namespace tumble::render
