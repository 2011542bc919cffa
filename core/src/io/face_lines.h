// Where each face of a soup was read, for messages: the line of each face (0: unknown), kept as
// runs, since a text file's faces mostly follow each other a line apart (a line number per face
// took 8 bytes a face, 8 MB at the peak of reading a 1M-face OBJ, for a message about a bad
// index that most files never need).
#pragma once

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace holefill::io {

class FaceLines {
 public:
  // Face `face`, added after every face before it (those not added have no known line), was read
  // on line `line` (0: unknown).
  void add(std::size_t face, std::size_t line) {
    if (!runs_.empty() && line_in_last_run(face) == line) return;
    if (runs_.empty() && line == 0) return;
    runs_.push_back({face, line});
  }

  // The line face `face` was read on; 0 when unknown.
  std::size_t line(std::size_t face) const {
    const auto after =
        std::upper_bound(runs_.begin(), runs_.end(), face,
                         [](std::size_t f, const std::pair<std::size_t, std::size_t>& run) {
                           return f < run.first;
                         });
    if (after == runs_.begin()) return 0;
    const auto& run = *(after - 1);
    return run.second == 0 ? 0 : run.second + (face - run.first);
  }

  // Appends the lines of `later`'s `count` faces, which follow `faces` faces here and whose lines
  // count from `lines` lines of the file on, as one FaceLines of all the faces would hold them.
  void append(const FaceLines& later, std::size_t faces, std::size_t count, std::size_t lines) {
    // Later's faces before its first run have no known line.
    if (count > 0 && (later.runs_.empty() || later.runs_.front().first > 0)) add(faces, 0);
    for (const auto& [face, line] : later.runs_) add(faces + face, line == 0 ? 0 : lines + line);
  }

  // The runs: (face, its line); the faces after it, up to the next run's, on the lines after.
  const std::vector<std::pair<std::size_t, std::size_t>>& runs() const { return runs_; }

 private:
  // The line `face` has if it follows the last run's faces a line apart (0 in a run of unknown).
  std::size_t line_in_last_run(std::size_t face) const {
    const auto& [first, line] = runs_.back();
    return line == 0 ? 0 : line + (face - first);
  }

  std::vector<std::pair<std::size_t, std::size_t>> runs_;
};

}  // namespace holefill::io
