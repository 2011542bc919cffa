// The full search: the dynamic program of triangulate.h over every chord, O(n^3) time and
// 30 bytes per (i, k) cell, on one thread or several (the result is the same either way).
#pragma once

#include <cstddef>
#include <optional>

#include "holefill/triangulate.h"

namespace holefill::detail {

// The optimal triangulation under options.weight over all chords, or nothing when the forbidden
// chords leave none. The polygon needs at least 3 and fewer than kMaxPolygonSize points, and
// unit (or zero) outside normals. Runs on options.threads threads (0: as many as pay off).
// Waits, before it allocates its tables, until they fit in full_search_table_budget() beside
// those of the searches running at once (table_budget.h); a cancel ends the wait.
std::optional<PolygonTriangulation> full_search(const HolePolygon& polygon,
                                                const TriangulateOptions& options);

// The bytes of the full search's tables for a polygon of n points, with or without the cells'
// normals (weights with dihedral angles keep them).
std::size_t table_bytes(int n, bool keep_normals);

}  // namespace holefill::detail
