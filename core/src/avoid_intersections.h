// Intersection avoidance: on CAD parts (holes across sharp edges, long thin slots,
// boundaries far from planar) the weight's best triangulation of a hole can cut through the mesh
// around it, and refinement and smoothing cannot undo that. The planned triangles are checked
// against the mesh and each other before they are added; those that intersect are forbidden
// and the dynamic program solved again: a bounded number of rounds with the chosen weight, then
// with the other weights (keeping what was forbidden). The first intersection-free triangulation
// is kept: it is the weight's best among those without the forbidden triangles, so the patch
// keeps good triangles where the weight allows. When none is found the plan stays as it was.
#pragma once

#include "hole_triangulation.h"
#include "holefill/fill.h"
#include "mesh_face_index.h"

namespace holefill::detail {

// Returns `plan`, or a triangulation of `hole` that intersects nothing in its place. Reads the
// mesh only (the hole is not filled yet). `around` holds the mesh's faces by face index (or is
// null: the mesh is then scanned). Fills `report` and sets `pairs` to the intersecting pairs of
// the triangulation returned. With `exact_too`, the exact test joins the check
// (patch_intersections.h). Once options.progress is cancelled it returns `plan` at its next
// check (the caller, which asked, drops it).
PlannedTriangulation avoid_intersections(const Mesh& mesh, const Hole& hole,
                                         PlannedTriangulation plan,
                                         const TriangulateOptions& options,
                                         const MeshFaceIndex* around, IntersectionAvoidance& report,
                                         std::size_t& pairs, bool exact_too = false);

}  // namespace holefill::detail
