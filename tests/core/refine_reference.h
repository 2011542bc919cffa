// Refinement as it was written before the flat arrays (core/src/flat_patch.h): every centroid
// split and Delaunay swap an OpenMesh split(face, vertex) or flip(edge) on the mesh itself. The
// tests keep it as the reference that today's refine_patch must reproduce handle for handle.
#pragma once

#include <string>

#include "holefill/refine.h"

namespace holefill::testing {

// The relaxation's swap test by its definition, with four atan2: edge a-b between triangles
// (a, b, c) and (b, a, d) swaps when its opposite angles sum to more than pi + 1e-9 and the
// swapped edge's sum to less than theirs - 1e-9.
bool swap_by_angles(const Point& a, const Point& b, const Point& c, const Point& d);

// refine_patch as it was, without the remeshing (RefineOptions::remesh is ignored).
RefineResult reference_refine_patch(Mesh& mesh, Patch& patch, const RefineOptions& options);

// relax_patch_edges as it was.
std::size_t reference_relax_patch_edges(Mesh& mesh, const Patch& patch);

// The first way in which the two meshes differ, "" when they are the same handle for handle:
// counts, each vertex's position (bit for bit), halfedge, status, stage and scale, each
// halfedge's next, target and face, each face's halfedge, status and stage.
std::string first_difference(Mesh& expected, Mesh& actual);

}  // namespace holefill::testing
