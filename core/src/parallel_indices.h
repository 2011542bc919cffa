// Work on many independent items spread over threads: each thread takes the next item not yet
// taken, so large items first (the callers sort them so) balance with small ones. What an item's
// work throws (std::bad_alloc above all) never leaves its thread: it stops the others and is
// thrown again in the caller, once no thread runs.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <new>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

namespace holefill::detail {

// Calls work(i) once for each i in [0, count) that is reached, on up to `threads` threads (the
// calling one among them; fewer when no thread can be had), until stop() says so (checked before
// each item). When some work(i) throws, the items not yet taken are skipped and the exception
// of the lowest such i is rethrown here after every thread has finished.
template <class Work, class Stop>
void for_each_index(std::size_t count, unsigned threads, Work&& work, Stop&& stop) {
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::size_t failed_at = count;
  std::mutex failure_mutex;
  auto worker = [&] {
    for (std::size_t i = next++; i < count && !stop(); i = next++) {
      try {
        work(i);
      } catch (...) {
        next = count;
        const std::lock_guard lock(failure_mutex);
        if (i < failed_at) failed_at = i, failure = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  const std::size_t wanted =
      std::min<std::size_t>(std::max(1u, threads), std::max<std::size_t>(1, count));
  pool.reserve(wanted - 1);
  for (std::size_t t = 1; t < wanted; ++t) {
    try {
      pool.emplace_back(worker);
    } catch (const std::system_error&) {
      break;  // no thread to spare (memory, limits): the ones running share the items
    } catch (const std::bad_alloc&) {
      break;
    }
  }
  worker();
  for (auto& thread : pool) thread.join();
  if (failure) std::rethrow_exception(failure);
}

template <class Work>
void for_each_index(std::size_t count, unsigned threads, Work&& work) {
  for_each_index(count, threads, std::forward<Work>(work), [] { return false; });
}

// Calls work(begin, end, block) for the consecutive blocks [begin, end) of `per_block` indices
// that cover [0, count), on up to `threads` threads, as for_each_index calls work(i).
template <class Work>
void for_each_block(std::size_t count, std::size_t per_block, unsigned threads, Work&& work) {
  for_each_index((count + per_block - 1) / per_block, threads, [&](std::size_t block) {
    work(block * per_block, std::min(count, (block + 1) * per_block), block);
  });
}

}  // namespace holefill::detail
