// Two pieces of work on two threads: the two parts of a big text file (two_parts.h), and the
// independent parts of a big mesh's assembly (soup_to_mesh, mesh_from_triangles,
// soup_attributes). In the assembly, each part writes only what is its own (its half of an array,
// its own counters), and what depends on order is put back in order, so the mesh, the report and
// every message are the one-thread assembly's.
#pragma once

#include <cstddef>
#include <exception>
#include <system_error>
#include <thread>

#include "../available_cores.h"

namespace holefill::io {

// From this many faces on, the assembly uses a second thread where the machine has more than one
// core (below, starting a thread costs more than it saves).
inline constexpr std::size_t kTwoThreadsFrom = std::size_t{1} << 15;
// A `from` that no mesh reaches: one thread whatever the size (a caller asked for one).
inline constexpr std::size_t kOneThreadAlways = ~std::size_t{0};

// Whether assembling `faces` faces uses two threads, from `from` faces on.
inline bool use_two_threads(std::size_t faces, std::size_t from) {
  return faces >= from && detail::available_cores() > 1;
}

// Runs `second` on a thread of its own and `first` here when `two`, else (or when no thread can
// be had) first, then second, here. What either throws is thrown here once neither runs (the
// first's when both throw).
template <class First, class Second>
void run_both(bool two, First&& first, Second&& second) {
  std::exception_ptr second_error;
  std::thread thread;
  if (two) {
    try {
      thread = std::thread([&] {
        try {
          second();
        } catch (...) {
          second_error = std::current_exception();
        }
      });
    } catch (const std::system_error&) {  // no thread to be had: one after the other
    }
  }
  try {
    first();
  } catch (...) {
    if (thread.joinable()) thread.join();
    throw;
  }
  if (!thread.joinable()) return second();
  thread.join();
  if (second_error) std::rethrow_exception(second_error);
}

// Calls part(begin, end) on [0, middle) here and on [middle, count) on a second thread when
// `two` (middle = count / 2), else once on [0, count).
template <class Part>
void run_in_halves(bool two, std::size_t count, Part&& part) {
  if (!two) return part(std::size_t{0}, count);
  const std::size_t middle = count / 2;
  run_both(
      true, [&] { part(std::size_t{0}, middle); }, [&] { part(middle, count); });
}

}  // namespace holefill::io
