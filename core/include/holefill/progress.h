// A long operation's progress and a way to stop it, shared between the thread doing the work and
// one watching it (a viewer's frame loop, a command line's progress line). The work reports the
// share done and checks cancelled() only where stopping leaves everything consistent (between
// holes); what "stopped" leaves behind is stated by each function that takes a Progress.
#pragma once

#include <atomic>
#include <functional>
#include <utility>

namespace holefill {

class Progress {
 public:
  Progress() = default;
  // `on_report` is called with each fraction the work sets, on the work's thread(s), possibly
  // several at once: it must be thread-safe. It may call cancel().
  explicit Progress(std::function<void(double)> on_report) : on_report_(std::move(on_report)) {}

  // Asks the work to stop at its next check. Any thread, any time.
  void cancel() noexcept { cancelled_.store(true, std::memory_order_relaxed); }
  bool cancelled() const noexcept { return cancelled_.load(std::memory_order_relaxed); }

  // The share of the work done, from 0 to 1; set by the work, read by anyone.
  void set_fraction(double fraction) {
    fraction_.store(fraction, std::memory_order_relaxed);
    if (on_report_) on_report_(fraction);
  }
  double fraction() const noexcept { return fraction_.load(std::memory_order_relaxed); }

 private:
  std::atomic<bool> cancelled_{false};
  std::atomic<double> fraction_{0.0};
  std::function<void(double)> on_report_;
};

// The reason a stage stopped by a cancel gives (HoleFill::failure, FairResult::problem).
inline constexpr char kCancelledReason[] = "cancelled";

// Whether `progress` asks the work to stop; a null one never does.
inline bool is_cancelled(const Progress* progress) noexcept {
  return progress != nullptr && progress->cancelled();
}

}  // namespace holefill
