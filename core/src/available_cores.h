// How many cores this process may run on: the CPUs of its affinity mask (taskset, cgroups' cpusets,
// a batch scheduler's allocation), which std::thread::hardware_concurrency() does not see (it
// counts every online CPU, so a process pinned to one core would start a thread per CPU on it).
#pragma once

#include <sched.h>

#include <algorithm>
#include <thread>

namespace holefill::detail {

// At least 1.
inline unsigned available_cores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0) {
    return static_cast<unsigned>(std::max(1, CPU_COUNT(&set)));
  }
  return std::max(1u, std::thread::hardware_concurrency());
}

}  // namespace holefill::detail
