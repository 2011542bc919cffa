#include "progress_lines.h"

#include <ostream>
#include <string>

#include "table.h"

namespace holefill::cli {

ProgressLines::ProgressLines(std::ostream& err, std::string input, bool always)
    : err_(err),
      input_(std::move(input)),
      always_(always),
      progress_([this](double fraction) { print(fraction); }) {}

void ProgressLines::print(double fraction) {
  const auto now = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(now - start_).count();
  if (!always_ && seconds < 1.0) return;
  // fill_holes reports triangulations as the first half of the work, added patches as the second.
  const bool triangulating = fraction <= 0.5;
  const double share = triangulating ? 2.0 * fraction : 2.0 * fraction - 1.0;
  const std::string percent = format("%.0f", 100.0 * share);
  // Threads report out of order: a line only when the phase or its whole percentage moves on.
  const int step = (triangulating ? 0 : 1000) + std::stoi(percent);
  const std::lock_guard lock(mutex_);
  if (step <= last_step_) return;
  // Without -v, a line a second at most, and each phase's last.
  const bool phase_done = percent == "100";
  if (!always_ && !phase_done && last_step_ >= 0 && now - last_line_ < std::chrono::seconds(1)) {
    return;
  }
  last_step_ = step;
  last_line_ = now;
  err_ << "holefill: " << input_ << ": " << (triangulating ? "holes triangulated" : "patches added")
       << " " << percent << " % (" << format("%.1f", seconds) << " s)\n";
}

}  // namespace holefill::cli
