// holefill.Fill: one hole filled a stage at a time (triangulate, refine, smooth), with undo, to
// look at each step in a notebook: advance_joined (fill.h) on the hole and the loops filled with
// it, as fill() would group them.
#pragma once

#include <pybind11/pybind11.h>

namespace holefill::python {

void bind_stage_fill(pybind11::module_& module);

}  // namespace holefill::python
