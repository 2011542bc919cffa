// Fewer page faults for the big arrays a load fills once: the kernel is asked to back them with
// transparent huge pages (2 MB), where a fault per 4 KB page was a large part of loading a big
// mesh (on a virtual machine, several microseconds each: a quarter to a half of a 1M-face load).
#pragma once

#include <algorithm>
#include <cstddef>
#include <limits>
#include <memory>
#include <type_traits>
#include <vector>

namespace holefill::io {

// The size of a huge page (x86-64's and most systems' transparent huge pages).
inline constexpr std::size_t kHugePageBytes = std::size_t{2} << 20;

// Asks for huge pages under the whole 2 MB pages inside [data, data + bytes), which should not be
// written yet (pages already there stay as they are). Only the pages the range covers whole are
// asked for, so no memory beyond the range is made resident. Does nothing where the system has
// no such advice, or the range covers no whole huge page.
void prefer_huge_pages(const void* data, std::size_t bytes);

// Reserves room for `count` elements in the empty `array` (no copy is made later while it grows to
// that many) and asks for huge pages under the first `likely` of them (all by default: a room
// larger than what is filled would be made resident up to its last whole huge page).
template <class T>
void reserve_on_huge_pages(std::vector<T>& array, std::size_t count,
                           std::size_t likely = std::numeric_limits<std::size_t>::max()) {
  array.reserve(count);
  prefer_huge_pages(array.data(), std::min(count, likely) * sizeof(T));
}

// Frees what huge_page_array allocated.
struct HugePageFree {
  void operator()(void* data) const;
};

// An array of `count` elements of an implicit-lifetime type T (uninitialised), aligned on a huge
// page and on huge pages.
template <class T>
using HugePageArray = std::unique_ptr<T[], HugePageFree>;

void* allocate_on_huge_pages(std::size_t bytes);

template <class T>
HugePageArray<T> huge_page_array(std::size_t count) {
  static_assert(std::is_trivially_default_constructible_v<T> &&
                std::is_trivially_destructible_v<T>);
  return HugePageArray<T>(static_cast<T*>(allocate_on_huge_pages(count * sizeof(T))));
}

// A vector of `count` copies of `value` on huge pages.
template <class T>
std::vector<T> huge_page_vector(std::size_t count, const T& value) {
  std::vector<T> array;
  reserve_on_huge_pages(array, count);
  array.assign(count, value);
  return array;
}

}  // namespace holefill::io
