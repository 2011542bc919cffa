#include "thread_counter.h"

#include <dlfcn.h>
#include <pthread.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <new>

namespace holefill::testing {
namespace {

std::atomic<std::size_t> started{0};
std::atomic<std::size_t> running{0};
std::atomic<std::size_t> most_running{0};

using Create = int (*)(pthread_t*, const pthread_attr_t*, void* (*)(void*), void*);

Create real_create() {
  static const Create real = reinterpret_cast<Create>(dlsym(RTLD_NEXT, "pthread_create"));
  return real;
}

struct Start {
  void* (*routine)(void*);
  void* argument;
};

// The thread's own routine, between a count on entry and one on return.
void* counted(void* start_pointer) {
  const Start start = *static_cast<Start*>(start_pointer);
  delete static_cast<Start*>(start_pointer);
  const std::size_t now = ++running;
  std::size_t most = most_running.load();
  while (now > most && !most_running.compare_exchange_weak(most, now)) {
  }
  void* result = start.routine(start.argument);
  --running;
  return result;
}

}  // namespace

void reset_thread_counts() {
  started = 0;
  most_running = running.load();
}

ThreadCounts thread_counts() { return {started.load(), most_running.load()}; }

}  // namespace holefill::testing

extern "C" int pthread_create(pthread_t* thread, const pthread_attr_t* attributes,
                              void* (*routine)(void*), void* argument) noexcept {
  using namespace holefill::testing;
  const Create real = real_create();
  auto* start = new (std::nothrow) Start{routine, argument};
  if (real == nullptr || start == nullptr) {
    delete start;
    return EAGAIN;
  }
  const int failed = real(thread, attributes, counted, start);
  if (failed) {
    delete start;
  } else {
    ++started;
  }
  return failed;
}
