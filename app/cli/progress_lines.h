// Progress lines on stderr while `holefill fill` works: one as each hole is triangulated and as
// each patch is added, once the run has taken a second (from the start with -v), so that a long
// run shows it is alive and a short one stays quiet.
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
  std::mutex mutex_;  // fill_holes reports from several threads at once
  Progress progress_;
};

}  // namespace holefill::cli
