#include "progress_lines.h"

#include <ostream>

#include "table.h"

namespace holefill::cli {

ProgressLines::ProgressLines(std::ostream& err, std::string input, bool always)
    : err_(err),
      input_(std::move(input)),
      always_(always),
      progress_([this](double fraction) { print(fraction); }) {}

void ProgressLines::print(double fraction) {
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (!always_ && seconds < 1.0) return;
  // fill_holes reports triangulations as the first half of the work, added patches as the second.
  const bool triangulating = fraction <= 0.5;
  const double share = triangulating ? 2.0 * fraction : 2.0 * fraction - 1.0;
  const std::lock_guard lock(mutex_);
  err_ << "holefill: " << input_ << ": " << (triangulating ? "holes triangulated" : "patches added")
       << " " << format("%.0f", 100.0 * share) << " % (" << format("%.1f", seconds) << " s)\n";
}

}  // namespace holefill::cli
