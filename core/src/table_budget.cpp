#include "table_budget.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>

namespace holefill::detail {

TableBudget::Lease TableBudget::acquire(std::size_t bytes, const std::function<bool()>& abandon) {
  std::unique_lock lock(mutex_);
  const auto fits = [&] { return leases_ == 0 || held_ + bytes <= budget_; };
  while (!fits()) {
    if (abandon && abandon()) return {};
    freed_.wait_for(lock, std::chrono::milliseconds(20));
  }
  held_ += bytes;
  ++leases_;
  peak_ = std::max(peak_, held_);
  return Lease(this, bytes);
}

void TableBudget::release(std::size_t bytes) {
  {
    const std::lock_guard lock(mutex_);
    held_ -= bytes;
    --leases_;
  }
  freed_.notify_all();
}

std::size_t TableBudget::peak_held() const {
  const std::lock_guard lock(mutex_);
  return peak_;
}

void TableBudget::set_budget(std::size_t bytes) {
  {
    const std::lock_guard lock(mutex_);
    budget_ = bytes;
    peak_ = held_;
  }
  freed_.notify_all();
}

TableBudget& full_search_table_budget() {
  static TableBudget budget([] {
    constexpr std::size_t kOneLargestSearch = std::size_t{256} << 20;
    const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGE_SIZE);
    if (pages <= 0 || page_size <= 0) return kOneLargestSearch;
    const std::size_t physical =
        static_cast<std::size_t>(pages) * static_cast<std::size_t>(page_size);
    return std::max(kOneLargestSearch, physical / 4);
  }());
  return budget;
}

}  // namespace holefill::detail
