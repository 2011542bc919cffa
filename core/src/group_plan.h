// fill_holes' use of the loop groups (loop_groups.h): which groups a HoleSelection takes, and the
// triangulation planned for each (fill_groups.cpp plans them on every thread).
#pragma once

#include <vector>

#include "holefill/bridge.h"
#include "holefill/hole_selection.h"
#include "holefill/holes.h"
#include "holefill/loop_groups.h"
#include "holefill/mesh.h"
#include "holefill/triangulate.h"

namespace holefill::detail {

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

}  // namespace holefill::detail
