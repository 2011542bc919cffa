// Which boundary loops fill_holes closes with one patch: a hole alone, a hole with its islands
// (islands.h), or holes bridged into one band (HoleSelection::bridges in hole_selection.h,
// bridge.h).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "holefill/bridge.h"
#include "holefill/failure.h"
#include "holefill/holes.h"
#include "holefill/islands.h"
#include "holefill/mesh.h"

namespace holefill {

struct LoopGroup {
  std::vector<int> holes;  // hole ids: the outer hole (or the first bridged one) first
  Failure problem;         // why the group cannot be filled; then none of its loops is
  std::string note;        // why a loop inside the hole was left out of it (islands.h)
  std::size_t boundary_edges(const std::vector<Hole>& all) const;
};

// Every loop of `holes` in exactly one group: each bridged pair with the islands of both, each
// hole with its islands (as `islands` found them), every other hole alone. A group carries a
// problem when a loop of it has one in `islands`, when a hole is bridged twice or bridged while
// an island, when a bridge names a hole twice, or when bridged loops are farther apart than
// options.max_gap times the larger one's diameter. Hole ids in `bridges` must exist.
std::vector<LoopGroup> group_loops(const Mesh& mesh, const std::vector<Hole>& holes,
                                   const IslandMap& islands,
                                   const std::vector<std::pair<int, int>>& bridges,
                                   const JoinOptions& options = {});

}  // namespace holefill
