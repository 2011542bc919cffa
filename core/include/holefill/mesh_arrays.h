// A Mesh from arrays, as a scripting language holds a mesh (numpy's vertices and faces), through
// the checks and repairs a loaded file gets (io.h): the same mesh as load_mesh gives for a file
// with these positions, triangles and attributes.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "holefill/attributes.h"
#include "holefill/io.h"
#include "holefill/mesh.h"

namespace holefill {

struct MeshArrays {
  std::vector<Point> positions;
  std::vector<std::array<std::int64_t, 3>> triangles;  // indices into positions
  // Attributes as a loaded file carries them (attributes.h): layout.vertex[c] names the column
  // vertex_values[c] (one value per position), layout.face[c] the column face_values[c].
  AttributeLayout layout;
  std::vector<std::vector<double>> vertex_values;
  std::vector<std::vector<double>> face_values;
};

// The mesh the arrays describe. Throws InvalidMeshError naming `name` (it stands in for a file's
// path) and the element: a non-finite coordinate, an index outside the positions, a column whose
// length is not the positions' or the triangles' count, no face left after the repairs. The
// repairs are counted in `report` (its format is "arrays"), with a warning for each kind.
Mesh mesh_from_arrays(MeshArrays arrays, const std::string& name, LoadReport* report = nullptr);

}  // namespace holefill
