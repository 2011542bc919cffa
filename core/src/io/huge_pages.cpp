#include "huge_pages.h"

#include <cstdint>
#include <new>
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace holefill::io {
void prefer_huge_pages(const void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  const auto begin = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t first = (begin + kHugePageBytes - 1) & ~(kHugePageBytes - 1);
  const std::uintptr_t last = (begin + bytes) & ~(kHugePageBytes - 1);
  if (data == nullptr || last <= first) return;
  // Advice only: where it is refused (no transparent huge pages), the pages are the usual ones.
  madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#else
  (void)data;
  (void)bytes;
#endif
}

void* allocate_on_huge_pages(std::size_t bytes) {
  void* data = ::operator new (bytes, std::align_val_t{kHugePageBytes});
  prefer_huge_pages(data, bytes);
  return data;
}

void HugePageFree::operator()(void* data) const {
  ::operator delete (data, std::align_val_t{kHugePageBytes});
}

}  // namespace holefill::io
