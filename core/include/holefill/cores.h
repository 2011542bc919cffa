// How many cores this process may run on, which is what a count of threads of 0 means throughout
// the library (FillOptions::threads, PrepareOptions::threads, load_mesh's threads): front ends
// that run several fills at once share these among them.
#pragma once

namespace holefill {

// The CPUs of the process's affinity mask (taskset, cgroups' cpusets, a batch scheduler's
// allocation), which std::thread::hardware_concurrency() does not see; at least 1.
unsigned available_cores();

}  // namespace holefill
