// Triangulating one hole of a mesh, in two steps so that fill_holes can plan many holes at once
// on several threads and add their patches one by one (internal: the pipeline of fill.h is the
// public way to fill a hole).
#pragma once

#include <optional>
#include <string>

#include "holefill/holes.h"
#include "holefill/mesh.h"
#include "holefill/patch.h"
#include "holefill/triangulate.h"

namespace holefill::detail {

// The hole's polygon as the dynamic program sees it: points, the normals of the faces across its
// edges, and the chords that already exist in the mesh.
HolePolygon hole_polygon(const Mesh& mesh, const Hole& hole);

struct TriangulateHoleResult {
  std::optional<Patch> patch;  // set when the hole was triangulated
  Failure failure;             // why not, otherwise
};

// The most times a hole's boundary may pass through one vertex for a patch to be planned: a
// loop passing a vertex that often runs around a fan of pieces meeting only there (5,000 lone
// triangles around one vertex made one 15,000-edge loop, planned for 145 s in 3.3 GB, whose patch
// crossed itself), not around a hole.
inline constexpr int kMaxVertexPasses = 16;

// The hole's triangulation, or why there is none (e.g. more than kMaxVertexPasses passes through
// one vertex). Reads the mesh only, so plans for several holes can be made at once on several
// threads.
PlannedTriangulation plan_triangulation(const Mesh& mesh, const Hole& hole,
                                        const TriangulateOptions& options);

// Adds a planned triangulation's triangles to the mesh (tagged Stage::Triangulated). On failure
// the mesh is left exactly as it was.
TriangulateHoleResult apply_triangulation(Mesh& mesh, const Hole& hole,
                                          const PlannedTriangulation& plan);

}  // namespace holefill::detail
