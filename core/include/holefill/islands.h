// Islands: a piece of surface floating inside a hole, as scans leave them. Loop I is an island of
// hole O when
//   - I lies on another connected component of the mesh than O (an island is a separate piece);
//   - projected onto O's plane (through O's centroid, normal to O's vector area, the plane onto
//     which O projects with the largest area) I lies strictly inside O's outline, crossing none
//     of its edges;
//   - I runs the other way round than O in that projection (so the region between them has one
//     orientation: a flipped piece is not an island);
//   - every vertex of I lies within `reach` times O's radius (its largest distance from its
//     centroid) of that plane, the height a patch over O could bulge to.
// When several holes qualify and one lies inside the others, the innermost one takes the island;
// otherwise (an island of two holes) neither takes it: each is filled without it, and it is a loop
// filled on its own. So is a loop that would be an island but comes within a tenth of the
// surrounding edge length of O's loop (or shares a vertex with it): it touches O, and a patch
// between them would be pinched; and an island with islands of its own (its hole is filled without
// it, and it with its islands). Each such doubt leaves a note on the loops it concerns. Filling
// then joins each hole with its islands by bridge edges (bridge.h).
#pragma once

#include <string>
#include <vector>

#include "holefill/holes.h"
#include "holefill/mesh.h"

namespace holefill {

struct IslandOptions {
  bool detect = true;  // false: every loop is filled on its own (CLI --islands off)
  double reach = 1.0;  // how far from the outer hole's plane an island may lie, in its radius
  bool operator==(const IslandOptions&) const = default;
};

// What find_islands found, indexed by hole id.
struct IslandMap {
  std::vector<std::vector<int>> islands;  // the islands of each hole (empty for most)
  std::vector<int> outer;                 // the hole each island lies in; -1 for other loops
  // Why a hole is filled without a loop that looked like its island, or why a loop is filled on
  // its own though it lies inside a hole (an island of two holes, one touching its hole's loop,
  // one with islands of its own). Empty for the others.
  std::vector<std::string> note;

  bool has_islands(int hole) const { return !islands[hole].empty(); }
};

// The islands among `holes` (find_holes(mesh)). With options.detect false, none.
IslandMap find_islands(const Mesh& mesh, const std::vector<Hole>& holes,
                       const IslandOptions& options = {});
// find_islands where `component` is component_labels(mesh) (stats.h), found already (beside
// other work); unused when options.detect is false or there are fewer than two holes.
IslandMap find_islands(const Mesh& mesh, const std::vector<Hole>& holes,
                       const IslandOptions& options, const std::vector<int>& component);

}  // namespace holefill
