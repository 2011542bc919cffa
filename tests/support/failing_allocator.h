// Makes operator new throw std::bad_alloc on demand, to test what running out of memory does:
// allocations on threads other than the caller's, or allocations larger than a size. Linking
// this replaces the program's operator new and delete (with malloc and free, so sanitizers see
// matching pairs); until asked, every allocation behaves as usual.
#pragma once

#include <cstddef>

namespace holefill::testing {

// From now on, allocations on any thread but the calling one fail.
void fail_allocations_off_this_thread();

// From now on, allocations of more than `bytes` fail, on every thread.
void fail_allocations_larger_than(std::size_t bytes);

// How many allocations have been made to fail so far, on every thread.
std::size_t failed_allocations();
// Allocations succeed again.
void stop_failing_allocations();

}  // namespace holefill::testing
