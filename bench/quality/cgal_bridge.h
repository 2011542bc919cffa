// Our meshes handed to CGAL's hole filling and fairing (cgal_fill.h) and read back into our mesh
// type, vertex and face indices unchanged. Built only when CMake finds CGAL.
#pragma once

#include <cstddef>
#include <vector>

#include "holefill/holes.h"
#include "holefill/mesh.h"
#include "measure.h"

namespace holefill::quality {

// CGAL's filling (triangulate_refine_and_fair_hole) of each of `loops`, holes of `cut`: the
// filled mesh, one patch per loop appended to `patches` (in the loops' order), and `unfaired`
// raised by the number of patches CGAL reports it could not fair.
Mesh fill_with_cgal(const Mesh& cut, const std::vector<Hole>& loops,
                    std::vector<FilledHole>& patches, std::size_t& unfaired);

// Our triangulation and refinement, then CGAL's fairing of the new vertices: tells whether a
// difference to CGAL comes from the fairing or from the patch it starts from. False where CGAL
// failed on some patch (those positions unchanged).
bool fair_with_cgal(Mesh& mesh, const std::vector<FilledHole>& patches);

}  // namespace holefill::quality
