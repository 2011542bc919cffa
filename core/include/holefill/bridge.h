// Filling a region bounded by several boundary loops with one patch: a hole with islands, or the
// gap between two surfaces (the paper's future work, Sec. V). Bridge edges join the loops into one
// polygon: it walks the first loop, crosses a bridge to the next loop, goes once around that loop
// and comes back over the same bridge, so it visits each bridge's two endpoints twice. Chords
// between the two copies of a vertex, and chords that would repeat a bridge, are forbidden; the
// dynamic program of triangulate.h then triangulates the polygon like any hole, and the patch is
// an annulus (or a disk with several holes) whose triangles follow every loop's orientation.
// Each bridge is chosen by the same weight: among the shortest candidate bridges from a loop to
// the polygon built so far, the one whose polygon triangulates best (the dihedral angle across the
// bridge included), so the paper's max-min angle decides first.
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
  bool operator==(const JoinOptions&) const = default;
};

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
// built so far, so an island may hang from another island) and plans the triangulation of the
// result. On failure (fewer than two loops, loops that share a vertex or pass twice through one,
// a polygon too large, no candidate bridge that gives a valid triangulation) plan.failure says why
// and plan.triangulation is empty. Reads the mesh only.
JoinedLoops plan_joined_loops(const Mesh& mesh, const std::vector<const Hole*>& loops,
                              const TriangulateOptions& options, const JoinOptions& join = {});

// Whether a triangulation of the joined polygon makes a manifold patch: no directed edge used
// twice (which a chord repeating another chord between copies of the same vertices would do).
bool is_manifold_triangulation(const Hole& polygon,
                               const std::vector<std::array<int, 3>>& triangles);

}  // namespace holefill
