#include "python_progress.h"

namespace py = pybind11;

namespace holefill::python {

PythonProgress::PythonProgress(py::object callback)
    : callback_(std::move(callback)), progress_([this](double fraction) { report(fraction); }) {
  if (!callback_.is_none() && !PyCallable_Check(callback_.ptr())) {
    throw py::type_error("progress must be callable(fraction) or None");
  }
}

PythonProgress::~PythonProgress() = default;

void PythonProgress::report(double fraction) {
  const py::gil_scoped_acquire gil;
  if (progress_.cancelled()) return;
  // Signal handlers run on the main thread only: a fill called there notices Ctrl-C when it
  // reports from that thread.
  if (PyErr_CheckSignals() != 0) {
    error_.emplace();
    progress_.cancel();
    return;
  }
  if (callback_.is_none()) return;
  try {
    const py::object answer = callback_(fraction);
    if (py::isinstance<py::bool_>(answer) && !answer.cast<bool>()) progress_.cancel();
  } catch (py::error_already_set& e) {
    error_.emplace(std::move(e));
    progress_.cancel();
  }
}

void PythonProgress::raise_if_failed() {
  if (!error_) return;
  py::error_already_set error = std::move(*error_);
  error_.reset();
  throw error;
}

}  // namespace holefill::python
