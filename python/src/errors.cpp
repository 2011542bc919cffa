#include "errors.h"

#include <sstream>

#include "commands.h"
#include "holefill/errors.h"

namespace py = pybind11;

namespace holefill::python {
namespace {

// Created once, with the module, and never freed: the interpreter may outlive any static.
PyObject* warning_type = nullptr;

}  // namespace

void bind_errors(py::module_& module) {
  static py::exception<Error> error(module, "Error", PyExc_ValueError);
  error.doc() =
      "A file that cannot be read or written, a mesh holefill cannot use, or an option out of "
      "its range; the message is the one the holefill command prints.";
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const Error& e) {
      error(e.what());
    } catch (const cli::UsageError& e) {
      error(e.what());
    }
  });
  warning_type = PyErr_NewExceptionWithDoc(
      "holefill.HolefillWarning",
      "What holefill repaired or noticed in a mesh (the lines the command prints on stderr).",
      PyExc_UserWarning, nullptr);
  if (!warning_type) throw py::error_already_set();
  module.attr("HolefillWarning") = py::handle(warning_type);
}

void warn_lines(const std::string& text) {
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("holefill: ", 0) == 0) line.erase(0, 10);  // the command line's prefix
    if (line.empty()) continue;
    if (PyErr_WarnEx(warning_type, line.c_str(), 2) != 0) throw py::error_already_set();
  }
}

}  // namespace holefill::python
