// A long operation's progress and a way to stop it, shared between the thread doing the work and
// one watching it (a viewer's frame loop, a command line's progress line). The work reports the
// share done and checks cancelled() only where stopping leaves everything consistent (between
// holes); what "stopped" leaves behind is stated by each function that takes a Progress.
#pragma once

#include <atomic>
#include <functional>
#include <string_view>
#include <utility>

namespace holefill {

class Progress {
 public:
  Progress() = default;
  // `on_report` is called with each fraction the work sets, on the work's thread(s), possibly
  // several at once: it must be thread-safe. It may call cancel().
  explicit Progress(std::function<void(double)> on_report) : on_report_(std::move(on_report)) {}
  // `on_phase` is also called, on the work's thread, with the name of each long phase (the
  // constants below) as the work enters it: a watcher may show it, and a test may cancel there.
  Progress(std::function<void(double)> on_report, std::function<void(std::string_view)> on_phase)
      : on_report_(std::move(on_report)), on_phase_(std::move(on_phase)) {}

  // Asks the work to stop at its next check. Any thread, any time.
  void cancel() noexcept { cancelled_.store(true, std::memory_order_relaxed); }
  bool cancelled() const noexcept { return cancelled_.load(std::memory_order_relaxed); }

  // The share of the work done, from 0 to 1; set by the work, read by anyone.
  void set_fraction(double fraction) {
    fraction_.store(fraction, std::memory_order_relaxed);
    if (on_report_) on_report_(fraction);
  }
  double fraction() const noexcept { return fraction_.load(std::memory_order_relaxed); }

  // Said by the work as it enters a long phase (the work holds a const Progress).
  void enter_phase(std::string_view phase) const {
    if (on_phase_) on_phase_(phase);
  }

 private:
  std::atomic<bool> cancelled_{false};
  std::atomic<double> fraction_{0.0};
  std::function<void(double)> on_report_;
  std::function<void(std::string_view)> on_phase_;
};

// The long phases that say so (Progress::enter_phase), each of which looks at the cancel within
// a few hundred milliseconds. A phase lasts until the next is entered; a fill's stages enter
// theirs as they start.
namespace phase {
inline constexpr std::string_view kIndexingFaces = "indexing faces";  // before a fill's checks
inline constexpr std::string_view kTriangulating = "triangulating";
inline constexpr std::string_view kRefining = "refining";
inline constexpr std::string_view kRefiningBetweenCreases = "refining between creases";
inline constexpr std::string_view kSmoothing = "smoothing";
inline constexpr std::string_view kFactorising = "factorising";  // fairing's system
inline constexpr std::string_view kChecking = "checking intersections";
}  // namespace phase

// The reason a stage stopped by a cancel gives (HoleFill::failure, FairResult::problem).
inline constexpr char kCancelledReason[] = "cancelled";

// Whether `progress` asks the work to stop; a null one never does.
inline bool is_cancelled(const Progress* progress) noexcept {
  return progress != nullptr && progress->cancelled();
}

// progress->enter_phase(phase) unless `progress` is null.
inline void enter_phase(const Progress* progress, std::string_view phase) {
  if (progress) progress->enter_phase(phase);
}

}  // namespace holefill
