// Joining many loops into one polygon at a cost about linear in their vertices (bridge.h): a hole
// holding hundreds of small pieces. Weighing candidate bridges runs a dynamic program over the
// polygon built so far for each candidate of each loop, so its work grows with the square of the
// loops at least (100 pieces in one hole: 58 s; issue 32, #2). Here the loops are joined along a
// spanning tree in which each loop hangs from the loop it lies nearest to, by the shortest bridge
// between the two, and the polygon is written out in one walk around the tree.
#pragma once

#include <utility>
#include <vector>

#include "holefill/holes.h"
#include "holefill/mesh.h"

namespace holefill::detail {

struct LoopTree {
  // The joined polygon as bridge.h's JoinedLoops::polygon describes it (id of loops[0]; invalid
  // halfedges on bridges; a bridge's endpoints occur twice).
  Hole polygon;
  std::vector<std::pair<VertexHandle, VertexHandle>> bridges;  // one per loop after the first
};

// Joins loops[1], loops[2], ... to loops[0] by the edges of a spanning tree over the loops: in
// rounds (Boruvka's), every group of loops joined so far but the one with the most vertices takes
// the shortest bridge from one of its vertices to a vertex of another group, never one that an
// existing mesh edge already joins. Each round at least about halves the groups; a round costs a
// nearest-point search in a k-d tree per vertex, which skips the points of the searching group
// that lie nearer than any other group's. Needs at least two loops that share no vertex (bridge.h
// checks); reads the mesh only.
LoopTree join_along_tree(const Mesh& mesh, const std::vector<const Hole*>& loops);

// Chords (i, k), i < k, from a copy of a bridge's end that leave it outside the corner that copy
// has in the joined polygon (projected onto the polygon's plane, where the outer loop runs
// counter-clockwise and the islands the other way, each copy holds the wedge between its two
// polygon edges; the wedges of a vertex's copies do not overlap). Such a chord makes triangles
// that overlap others, and with its twin from the other copy an edge used twice. Only the chords
// the restricted search could take are looked at: to each copy's `nearest` nearest points and
// its `along` neighbours on either side along the polygon.
std::vector<std::pair<int, int>> chords_outside_corners(const Hole& joined,
                                                        const std::vector<Point>& points,
                                                        int nearest, int along);

}  // namespace holefill::detail
