// How the rows of the full search's table follow one another across threads (full_search.cpp):
// each strip of rows publishes, under its lowest row, the last column it has finished, and the
// strip above waits for a column before reading it. Release/acquire ordering makes a finished
// cell's values, and everything the row read before it, visible to the waiting row.
#pragma once

#include <atomic>
#include <thread>
#include <vector>

namespace holefill::detail {

class RowWavefront {
 public:
  explicit RowWavefront(int rows) : done_(static_cast<std::size_t>(rows)) {}

  // Row `row` has finished every cell up to `column`.
  void publish(int row, int column) {
    done_[static_cast<std::size_t>(row)].column.store(column, std::memory_order_release);
  }

  // Waits until row `row` has finished `column`; returns the last column it has finished (at
  // least `column`), so that the caller waits again only beyond it. Spins briefly (the row below
  // is usually a few cells ahead), then yields, so that a machine with more threads than cores
  // still lets the awaited row run.
  int wait_for(int row, int column) const {
    const auto& done = done_[static_cast<std::size_t>(row)].column;
    for (int attempt = 0;; ++attempt) {
      const int finished = done.load(std::memory_order_acquire);
      if (finished >= column) return finished;
      if (attempt < kSpinsBeforeYield) {
        pause();
      } else {
        std::this_thread::yield();
      }
    }
  }

 private:
  static constexpr int kSpinsBeforeYield = 64;

  static void pause() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
  }

  // One cache line per row, so that publishing a row does not disturb its neighbours' readers.
  struct alignas(64) Progress {
    std::atomic<int> column{-1};
  };
  std::vector<Progress> done_;
};

}  // namespace holefill::detail
