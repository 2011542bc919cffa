// Memory for the full search's tables, shared by the searches that run at once. fill_holes plans
// holes on every core, and a hole whose restricted triangulation folds runs the full search up to
// kMaxFullSearchEdges (243 MB of tables at 3,000 edges): on a machine with many cores, many such
// holes at once would hold many times that. A search waits here until its tables fit beside the
// others' within the budget; one search alone always runs, whatever its size.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>

namespace holefill::detail {

class TableBudget {
 public:
  explicit TableBudget(std::size_t bytes) : budget_(bytes) {}
  TableBudget(const TableBudget&) = delete;
  TableBudget& operator=(const TableBudget&) = delete;

  // Bytes held for one search until it is destroyed; empty when the wait was abandoned.
  class Lease {
   public:
    Lease() = default;
    Lease(TableBudget* budget, std::size_t bytes) : budget_(budget), bytes_(bytes) {}
    Lease(Lease&& other) noexcept : budget_(other.budget_), bytes_(other.bytes_) {
      other.budget_ = nullptr;
    }
    Lease& operator=(Lease&&) = delete;
    Lease(const Lease&) = delete;
    ~Lease() {
      if (budget_ != nullptr) budget_->release(bytes_);
    }
    bool held() const { return budget_ != nullptr; }

   private:
    TableBudget* budget_ = nullptr;
    std::size_t bytes_ = 0;
  };

  // Waits until `bytes` fit beside what the leases held now take (or none is held), then holds
  // them. Checks `abandon` every few milliseconds while waiting, and gives up (an empty lease) as
  // soon as it returns true.
  Lease acquire(std::size_t bytes, const std::function<bool()>& abandon = {});

  // The budget, and the most bytes held at once so far (what tests check).
  std::size_t budget() const { return budget_; }
  std::size_t peak_held() const;
  // Changes the budget for the leases acquired from now on, and starts peak_held() again from what
  // is held now (tests make the budget small).
  void set_budget(std::size_t bytes);

 private:
  void release(std::size_t bytes);

  mutable std::mutex mutex_;
  std::condition_variable freed_;
  std::size_t budget_;
  std::size_t held_ = 0;
  int leases_ = 0;
  std::size_t peak_ = 0;
};

// The budget that every full search draws on: a quarter of the machine's physical memory, and at
// least the tables of one search at kMaxFullSearchEdges.
TableBudget& full_search_table_budget();

}  // namespace holefill::detail
