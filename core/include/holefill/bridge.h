// Filling a region bounded by several boundary loops with one patch: a hole with islands, or the
// gap between two surfaces (the paper's future work, Sec. V). Bridge edges join the loops into one
// polygon: it walks the first loop, crosses a bridge to the next loop, goes once around that loop
// and comes back over the same bridge, so it visits each bridge's two endpoints twice. Chords
// between the two copies of a vertex, and chords that would repeat a bridge, are forbidden; the
// dynamic program of triangulate.h then triangulates the polygon like any hole, and the patch is
// an annulus (or a disk with several holes) whose triangles follow every loop's orientation.
// Each bridge is chosen by the same weight: among the shortest candidate bridges from a loop to
// the polygon built so far, the one whose polygon triangulates best (the dihedral angle across the
// bridge included), so the paper's max-min angle decides first. Many loops (a hole holding
// hundreds of small pieces) are joined along a tree of shortest bridges instead
// (JoinOptions::weighed_loops), at a cost about linear in their edges.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "holefill/holes.h"
#include "holefill/mesh.h"
#include "holefill/triangulate.h"

namespace holefill {

struct JoinOptions {
  // Bridges tried per joined loop (the shortest ones, one per vertex of the loop), each with a
  // full dynamic program over the joined polygon.
  int candidate_bridges = 6;
  // Holes bridged on request (HoleSelection::bridges) may be at most this many times the larger
  // loop's diameter apart (closest vertices): farther, a band between them is no gap to close.
  double max_gap = 2.0;
  // At most this many loops are joined to the first by weighing candidate bridges, and only while
  // the loops have at most TriangulateOptions::restricted.above_edges edges together (the full
  // search's polygons). Beyond, each loop hangs from the loop it lies nearest to by the shortest
  // bridge between them and the polygon is triangulated once: weighing runs candidate_bridges
  // dynamic programs per loop over the polygon built so far (100 small pieces in one hole took
  // 58 s that way, 400 over 300 s).
  int weighed_loops = 8;
  bool operator==(const JoinOptions&) const = default;
};

// The most loops joined into one polygon (a hole and 256 islands). Joining along a tree costs
// about linear time in any number of loops, but past kMaxFullSearchEdges only the restricted
// search runs, and it finds no valid triangulation of a polygon that runs around hundreds of
// pieces: a hole with 293 small pieces (2,440 edges joined) is filled in 0.6 s, one with 391
// (3,224 edges) is not.
inline constexpr std::size_t kMostJoinedLoops = 257;

struct JoinedLoops {
  // The joined polygon as a hole: id of the first loop; halfedges[i] is invalid where edge i is a
  // bridge; a bridge's endpoints occur twice in vertices.
  Hole polygon;
  std::vector<std::pair<VertexHandle, VertexHandle>> bridges;
  PlannedTriangulation plan;  // the triangulation of `polygon`, or why there is none
};

// `loop` spliced into `polygon` by a bridge from polygon.vertices[at_polygon] to
// loop.vertices[at_loop]: P0 ... Pi, Lj, Lj+1, ..., Lj-1, Lj, Pi, Pi+1, ... Pn-1.
Hole splice_loop(const Hole& polygon, const Hole& loop, int at_polygon, int at_loop);

// Joins loops[1], loops[2], ... to loops[0] (the nearest remaining loop first, each to the polygon
// built so far, so an island may hang from another island; beyond JoinOptions::weighed_loops, each
// by its shortest bridge to the loop it lies nearest to) and plans the triangulation of the
// result. On failure (fewer than two loops or more than kMostJoinedLoops, loops that share a vertex
// or pass twice through one, a polygon too large, no candidate bridge that gives a valid
// triangulation) plan.failure says why and plan.triangulation is empty. Reads the mesh only.
JoinedLoops plan_joined_loops(const Mesh& mesh, const std::vector<const Hole*>& loops,
                              const TriangulateOptions& options, const JoinOptions& join = {});

// Whether a triangulation of the joined polygon makes a manifold patch: no directed edge used
// twice (which a chord repeating another chord between copies of the same vertices would do).
bool is_manifold_triangulation(const Hole& polygon,
                               const std::vector<std::array<int, 3>>& triangles);

}  // namespace holefill
