#include "failing_allocator.h"

#include <atomic>
#include <cstdlib>
#include <limits>
#include <new>

namespace holefill::testing {
namespace {

std::atomic<bool> fail_off_thread{false};
std::atomic<std::size_t> largest_allowed{std::numeric_limits<std::size_t>::max()};
std::atomic<std::size_t> failures{0};
thread_local bool is_allowed_thread = false;

void* allocate(std::size_t size) {
  if (size > largest_allowed.load(std::memory_order_relaxed) ||
      (fail_off_thread.load(std::memory_order_relaxed) && !is_allowed_thread)) {
    failures.fetch_add(1, std::memory_order_relaxed);
    throw std::bad_alloc();
  }
  if (void* block = std::malloc(size == 0 ? 1 : size)) return block;
  throw std::bad_alloc();
}

}  // namespace

void fail_allocations_off_this_thread() {
  is_allowed_thread = true;
  fail_off_thread = true;
}

void fail_allocations_larger_than(std::size_t bytes) { largest_allowed = bytes; }

std::size_t failed_allocations() { return failures.load(std::memory_order_relaxed); }

void stop_failing_allocations() {
  fail_off_thread = false;
  largest_allowed = std::numeric_limits<std::size_t>::max();
}

}  // namespace holefill::testing

void* operator new(std::size_t size) { return holefill::testing::allocate(size); }
void* operator new[](std::size_t size) { return holefill::testing::allocate(size); }
void operator delete(void* block) noexcept { std::free(block); }
void operator delete[](void* block) noexcept { std::free(block); }
void operator delete(void* block, std::size_t) noexcept { std::free(block); }
void operator delete[](void* block, std::size_t) noexcept { std::free(block); }
// The nothrow forms too (std::stable_sort's buffer uses them): every block this program frees
// through the operators above must come from malloc, or AddressSanitizer reports a mismatch.
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return holefill::testing::allocate(size);
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept {
  return operator new(size, tag);
}
void operator delete(void* block, const std::nothrow_t&) noexcept { std::free(block); }
void operator delete[](void* block, const std::nothrow_t&) noexcept { std::free(block); }
