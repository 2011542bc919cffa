// The extension module holefill._holefill, which the package holefill re-exports.
#include <pybind11/pybind11.h>

#include "errors.h"
#include "fill_functions.h"
#include "holefill/version.h"
#include "mesh_object.h"
#include "stage_fill.h"

PYBIND11_MODULE(_holefill, module) {
  module.doc() = "holefill: fill holes in triangle meshes (Wei, Wu & Pang 2010).";
  module.attr("__version__") = HOLEFILL_VERSION;
  holefill::python::bind_errors(module);
  holefill::python::bind_mesh(module);
  holefill::python::bind_fill_functions(module);
  holefill::python::bind_stage_fill(module);
}
