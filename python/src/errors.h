// How holefill's C++ errors reach Python: holefill.Error (a ValueError) for bad input files,
// unusable meshes and bad options, with the command line's messages; MemoryError when memory runs
// out (pybind11's own translation of std::bad_alloc); and holefill.HolefillWarning (a
// UserWarning) for what the command line prints on stderr and the run goes on after.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

namespace holefill::python {

// Adds Error and HolefillWarning to `module` and translates holefill::Error and the command
// line's UsageError into Error.
void bind_errors(pybind11::module_& module);

// warnings.warn(line, HolefillWarning) for each line of `text` (with the GIL held), without the
// command line's "holefill: " in front; throws
// error_already_set when a warnings filter turned one into an exception.
void warn_lines(const std::string& text);

}  // namespace holefill::python
