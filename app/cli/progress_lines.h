// Progress lines on stderr while `holefill fill` works: as the holes are triangulated and as the
// patches are added, a line whenever the phase's whole percentage moves on (at most 101 a
// phase, however many holes), once the run has taken a second and then at most once a second
// besides each phase's 100 % line; from the start and at every step with -v. A long run shows
// it is alive, a short one stays quiet, and 20,000 holes do not print 40,000 lines.
#pragma once

#include <chrono>
#include <iosfwd>
#include <mutex>
#include <string>

#include "holefill/progress.h"

namespace holefill::cli {

class ProgressLines {
 public:
  // Lines name `input`; `always`: from the start rather than after a second.
  ProgressLines(std::ostream& err, std::string input, bool always);
  Progress& progress() { return progress_; }

 private:
  void print(double fraction);

  std::ostream& err_;
  std::string input_;
  bool always_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::mutex mutex_;    // fill_holes reports from several threads at once
  int last_step_ = -1;  // the last line's phase (0, 1000) plus its percentage; under mutex_
  std::chrono::steady_clock::time_point last_line_;  // when it was printed; under mutex_
  Progress progress_;
};

}  // namespace holefill::cli
