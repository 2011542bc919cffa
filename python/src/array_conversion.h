// numpy arrays to and from the arrays a mesh is made of (mesh_arrays.h): positions as float64,
// faces as int64, attributes as float64 columns. Inputs of other dtypes are converted where no
// value can change meaning (integers to float64 positions, any integer type to int64 faces) and
// refused otherwise (a float face index, complex or text values), naming the argument.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "holefill/attributes.h"
#include "holefill/mesh.h"
#include "holefill/mesh_arrays.h"

namespace holefill::python {

// vertices (n x 3), faces (m x 3) and the optional attributes of holefill.Mesh(...) as arrays
// for mesh_from_arrays. Throws holefill::Error (holefill.Error) naming the argument at fault.
MeshArrays arrays_from_python(pybind11::handle vertices, pybind11::handle faces,
                              pybind11::handle vertex_colors, pybind11::handle vertex_normals,
                              pybind11::handle vertex_attributes, pybind11::handle face_attributes);

// The mesh's positions (n x 3 float64) and faces (m x 3 int64, each face's corners in the order
// save_mesh writes them), as new arrays.
pybind11::array_t<double> vertex_array(const Mesh& mesh);
pybind11::array_t<std::int64_t> face_array(const Mesh& mesh);

// Colours in [0, 1] (n x 3 float64: red, green, blue over each type's full intensity) and normals
// (nx, ny, nz) when the mesh carries all three, else None.
pybind11::object color_array(const Mesh& mesh);
pybind11::object normal_array(const Mesh& mesh);

// Every vertex (or face) attribute the mesh carries: name -> float64 array of its values as held.
pybind11::dict vertex_attribute_arrays(const Mesh& mesh);
pybind11::dict face_attribute_arrays(const Mesh& mesh);

}  // namespace holefill::python
