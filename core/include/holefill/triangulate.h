// Step 1 of the paper: triangulating a hole's polygon by dynamic programming (Sec. II, Step 1).
//   w(i,k) = min over i<m<k of w(i,m) + w(m,k) + Phi(i,m,k),   O(i,k) = the best m,
// with the order and addition of the chosen weight (weights.h). Dihedral angles are taken
// against the triangles chosen for the two sub-polygons and, on edges of the hole's boundary,
// against the existing mesh face across that edge. Chords that already exist as mesh edges
// are rejected, so every weight yields a manifold patch.
#pragma once

#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "holefill/failure.h"
#include "holefill/mesh.h"
#include "holefill/progress.h"
#include "holefill/weights.h"

namespace holefill {

// The polygon P0 ... Pn-1 with what the dynamic program needs to know about its surroundings.
struct HolePolygon {
  std::vector<Point> points;
  // outside_normals[i]: unit normal of the mesh face across edge (Pi, Pi+1 mod n); a zero
  // vector where there is none (then that edge adds no dihedral angle).
  std::vector<Point> outside_normals;
  // Chords (i, k), i < k, that must not be used: they already exist as mesh edges, or join two
  // occurrences of the same vertex.
  std::vector<std::pair<int, int>> forbidden_chords;
  // Triangles (i, m, k), i < m < k, that must not be used either (e.g. because they cut through
  // the mesh: fill.h's intersection avoidance).
  std::vector<std::array<int, 3>> forbidden_triangles;
};

// The restricted search for large holes: chords inside pockets of
// consecutive boundary vertices, between anchors every pocket_edges/2 vertices, and to each
// vertex's nearest neighbours in space.
struct RestrictedSearch {
  std::size_t above_edges = 800;  // holes with more boundary edges use it; 0: never
  int pocket_edges = 48;
  int nearest_neighbours = 16;
  // Its triangulation is replaced by the full search's (never worse by the weight) when it has a
  // degenerate triangle or a dihedral angle above this (radians) and the polygon has at most
  // kMaxFullSearchEdges points: its chords follow the boundary, and along a long boundary with
  // steps (a hole cut from a scan's grid) every triangulation they hold folds over the steps.
  // pi or more: never.
  double full_search_above_dihedral = std::numbers::pi / 2;
  // false: the restricted search's answer stands, even when it finds nothing (the full search's
  // time grows with the cube of the edge count: ten seconds at 2,400 edges).
  bool full_search_fallback = true;
  bool operator==(const RestrictedSearch&) const = default;
};

struct TriangulateOptions {
  WeightKind weight = WeightKind::MaxMin;
  // maxmin: a largest dihedral angle beyond this (radians) is minimised before the smallest
  // angle is maximised; pi gives the paper's order exactly (see weights.h).
  double fold_limit = kDefaultFoldLimit;
  // Skip candidates that cannot beat a cell's best (same result, much faster); false runs the
  // plain O(n^3) loop, kept as the reference the fast path is tested against.
  bool prune = true;
  RestrictedSearch restricted{};
  // Threads for the full search: 0 chooses (one for small holes, where threads cost more than
  // they save, else every core this process may run on, shared with the searches running at the
  // same time); n uses n. The triangulation is the same whatever the number.
  unsigned threads = 0;
  // Checked between rows of the full search and between batches of the restricted one's chords:
  // once cancelled, the search stops and returns nothing (progress->cancelled() tells that from
  // "no triangulation"). Not owned; null: never cancelled.
  const Progress* progress = nullptr;
  bool operator==(const TriangulateOptions&) const = default;
};

// The dynamic program stores apexes in 16 bits: holes must have fewer boundary edges than this.
inline constexpr std::size_t kMaxPolygonSize = 0xFFFF;
// The full search needs 30 bytes per (i, k) cell (n^2 / 2 cells), 54 with the normals the
// maxmin and liepa weights keep: above this many edges (243 MB) only the restricted search runs.
inline constexpr std::size_t kMaxFullSearchEdges = 3000;

// The weight's components for a whole triangulation, whatever the weight: the quantities the
// paper's weights order, computed over all of the triangulation's triangles.
struct TriangulationQuality {
  double min_angle = 0.0;     // smallest interior angle of any triangle, radians
  double max_dihedral = 0.0;  // largest dihedral over interior and hole-boundary edges, radians
  double area = 0.0;
  int degenerate = 0;
};

struct PolygonTriangulation {
  // Triangles as polygon indices (i, m, k) with i < m < k, oriented like the hole's boundary.
  std::vector<std::array<int, 3>> triangles;
  TriangulationQuality quality;  // as the dynamic program accumulated it
};

// A polygon's triangulation, or why there is none.
struct PlannedTriangulation {
  std::optional<PolygonTriangulation> triangulation;
  Failure failure;  // set when triangulation is empty
};

// The optimal triangulation under options.weight, or nothing when the forbidden chords leave no
// valid triangulation. The polygon needs at least 3 and fewer than kMaxPolygonSize points.
// Polygons above options.restricted.above_edges go through the restricted search first (see
// RestrictedSearch), and through the full one when it finds nothing or a triangulation with a
// degenerate triangle or a fold (RestrictedSearch::full_search_above_dihedral), the polygon has
// at most kMaxFullSearchEdges points and RestrictedSearch::full_search_fallback allows it.
std::optional<PolygonTriangulation> triangulate_polygon(const HolePolygon& polygon,
                                                        const TriangulateOptions& options);

// The chords (i, k), i < k, the restricted search may use on this polygon (forbidden chords not
// removed), the closing edge (0, n-1) included. Each vertex joins few of them (pockets of
// anchors of anchors, not every pair of anchors), so the search's work grows about linearly.
std::vector<std::pair<int, int>> restricted_chords(const HolePolygon& polygon,
                                                   const RestrictedSearch& search);

// The restricted search alone (whatever the hole's size); nothing when the allowed chords hold no
// valid triangulation.
std::optional<PolygonTriangulation> triangulate_polygon_restricted(
    const HolePolygon& polygon, const TriangulateOptions& options);

// The value options.weight gives a triangulation of this quality (what the dynamic program
// minimises, up to its dihedral terms being taken against the neighbouring sub-polygons'
// triangles).
WeightValue weight_value(const TriangulationQuality& quality, const TriangulateOptions& options);

// Recomputes the quality of a given triangulation of `polygon` from scratch, edge by edge.
TriangulationQuality evaluate_triangulation(const HolePolygon& polygon,
                                            const std::vector<std::array<int, 3>>& triangles);

}  // namespace holefill
