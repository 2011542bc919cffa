// Which triangles of a patch intersect the mesh around them or each other (the test is
// triangle_intersection.h's), found through face grids (face_grid.h, mesh_face_index.h). A patch is
// given either as faces of the mesh or as corner positions of triangles not (yet) in it, so that a
// planned triangulation can be checked before it is added.
#pragma once

#include <array>
#include <vector>

#include "holefill/mesh.h"
#include "holefill/patch.h"
#include "holefill/progress.h"
#include "mesh_face_index.h"
#include "patch_face_set.h"

namespace holefill::detail {

// One intersecting pair: patch triangle `triangle` and either a later patch triangle
// (`other_triangle`) or a face of the mesh outside the patch (`other_face`, other_triangle -1).
struct IntersectingPair {
  int triangle = -1;
  int other_triangle = -1;
  FaceHandle other_face;
};

// The pairs of a patch triangle and another triangle (of the mesh outside the patch, or of the
// patch: each such pair once) that intersect other than along what they share; degenerate
// triangles are skipped. Faces of the mesh in `in_patch` (may be null: none) are not compared.
// `around` (when given) holds the mesh's faces outside the patch, by face index, so that only faces
// near the patch are looked at; otherwise the mesh is scanned. Safe for any finite coordinates:
// triangles are compared at a power-of-two scale that keeps products finite. With `exact_too`, a
// pair also counts when the independent exact test finds it (exact_triangle_intersection.h), so
// that what either test finds is found. Once `progress` is cancelled it stops within a few
// milliseconds, returning the pairs found so far (the caller, which asked, drops them).
std::vector<IntersectingPair> triangle_intersections(
    const Mesh& mesh, const std::vector<std::array<Point, 3>>& triangles,
    const PatchFaceSet* in_patch, const MeshFaceIndex* around, bool exact_too = false,
    const Progress* progress = nullptr);

// The chords (i, k), i < k, between non-neighbouring points of a hole's polygon whose segment
// passes through the interior of a face of the mesh (any triangle with such a side intersects
// it), in ascending order. `around` as for triangle_intersections. With `among`, only those
// chords (ascending, i < k) are tested: the restricted search's, on a hole it alone solves.
// Once `progress` is cancelled it stops as triangle_intersections does.
std::vector<std::pair<int, int>> chords_through_mesh(
    const Mesh& mesh, const std::vector<Point>& points, const MeshFaceIndex* around,
    const std::vector<std::pair<int, int>>* among = nullptr, const Progress* progress = nullptr);

// triangle_intersections for a patch already in the mesh; `triangle` indexes patch.faces.
std::vector<IntersectingPair> patch_intersections(const Mesh& mesh, const Patch& patch,
                                                  const MeshFaceIndex* around,
                                                  bool exact_too = false,
                                                  const Progress* progress = nullptr);

}  // namespace holefill::detail
