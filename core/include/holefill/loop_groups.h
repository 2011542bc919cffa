// Which boundary loops fill_holes closes with one patch: a hole alone, a hole with its islands
// (islands.h), or holes bridged into one band (HoleSelection::bridges, bridge.h), and the plan
// of each group's triangulation.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "holefill/bridge.h"
#include "holefill/failure.h"
#include "holefill/fill.h"
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

// Whether fill_holes takes the group: one of its holes is listed (or none are), and its loops
// have at most selection.max_boundary_edges edges together.
bool selects(const HoleSelection& selection, const LoopGroup& group,
             const std::vector<Hole>& holes);

struct GroupPlan {
  Hole polygon;  // the hole itself, or the loops joined by bridges
  PlannedTriangulation plan;
};

// The group's triangulation: plan_triangulation for a lone hole, plan_joined_loops otherwise;
// the group's problem as the failure when it has one.
GroupPlan plan_group(const Mesh& mesh, const std::vector<Hole>& holes, const LoopGroup& group,
                     const TriangulateOptions& options, const JoinOptions& join = {});

}  // namespace holefill
