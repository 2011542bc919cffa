// holefill.info, holefill.holes and holefill.fill: the command line's `info --json` and `fill`
// on a mesh held by Python, with the same preparation (stitching, small pieces, borders), the same
// hole ids and the same JSON records, as Python dicts.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

#include "fill_arguments.h"
#include "holefill/prepare.h"
#include "mesh_object.h"

namespace holefill::python {

// Prepares the mesh in place as `holefill fill` does before filling (prepare.h), with the lines
// the command prints appended to `notes`, and adds --holes and --bridge (a) to a.selection; throws
// UsageError (Python names in it) for an id the prepared mesh lacks. Runs without the GIL.
PreparedMesh prepare_in_place(MeshObject& object, cli::FillArguments& a, std::string& notes);

// A JSON text as Python values (json.loads).
pybind11::object from_json(const std::string& text);

// Adds info, holes, fill and FILL_OPTIONS to `module`.
void bind_fill_functions(pybind11::module_& module);

}  // namespace holefill::python
