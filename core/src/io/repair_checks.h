// Whether build_mesh's repairs of a soup's triangles (soup_repairs.h) have anything to do, decided
// on several threads in blocks of the edge uses. On a clean mesh (most big scans) none has, and
// the repairs' serial walks are skipped; where one has, the caller runs it as before, so the mesh
// is the one-thread mesh either way.
#pragma once

#include <vector>

#include "mesh_from_triangles.h"

namespace holefill::io {

// Whether two different triangles run along an edge that only they use the same way (orienting
// the triangles flips some).
bool any_edge_run_the_same_way(const EdgeUses& uses, unsigned threads);

// Whether an edge has more than two uses, or two running the same way (some triangle must be kept
// apart).
bool any_non_manifold_edge(const EdgeUses& uses, unsigned threads);

// Whether a vertex of `triangles` (their `uses`, every edge used at most twice) has more than one
// fan of triangles joined across their shared edges.
bool any_vertex_with_several_fans(const std::vector<Triangle>& triangles, const EdgeUses& uses,
                                  unsigned threads);

}  // namespace holefill::io
