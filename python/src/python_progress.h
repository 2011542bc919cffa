// A holefill::Progress that reports to a Python callable and stops the work on request: the
// callable gets the fraction done (0 to 1) and returns False to cancel; an exception it raises,
// or Ctrl-C (KeyboardInterrupt), cancels too and is raised again once the work has stopped.
// Reports come from the work's threads, which take the GIL for each.
#pragma once

#include <pybind11/pybind11.h>

#include <optional>

#include "holefill/progress.h"

namespace holefill::python {

class PythonProgress {
 public:
  // `callback`: None, or callable(fraction) -> bool | None. Constructed with the GIL held.
  explicit PythonProgress(pybind11::object callback);
  ~PythonProgress();
  PythonProgress(const PythonProgress&) = delete;
  PythonProgress& operator=(const PythonProgress&) = delete;

  Progress* progress() { return &progress_; }
  bool cancelled() const { return progress_.cancelled(); }
  // With the GIL held, after the work: raises what the callback raised, or the KeyboardInterrupt.
  void raise_if_failed();

 private:
  void report(double fraction);

  pybind11::object callback_;
  std::optional<pybind11::error_already_set> error_;  // under the GIL
  Progress progress_;
};

}  // namespace holefill::python
