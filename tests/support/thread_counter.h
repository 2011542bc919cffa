// Counts the threads a program starts, by standing in for pthread_create (which std::thread and
// std::jthread call) in the programs that link it: the thread-count tests only. Independent of
// the library: whatever starts a thread, through whichever of its helpers, is counted.
#pragma once

#include <cstddef>

namespace holefill::testing {

struct ThreadCounts {
  std::size_t started = 0;       // threads started since the last reset
  std::size_t most_at_once = 0;  // the most of them running at one time
};

// Starts counting afresh. Call with no thread of the program's running but the caller.
void reset_thread_counts();
ThreadCounts thread_counts();

}  // namespace holefill::testing
