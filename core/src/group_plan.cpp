#include "group_plan.h"

#include <algorithm>
#include <optional>
#include <utility>

#include "hole_triangulation.h"

namespace holefill::detail {

bool selects(const HoleSelection& selection, const LoopGroup& group,
             const std::vector<Hole>& holes) {
  if (selection.max_boundary_edges && group.boundary_edges(holes) > selection.max_boundary_edges) {
    return false;
  }
  const auto& ids = selection.hole_ids;
  return ids.empty() || std::any_of(group.holes.begin(), group.holes.end(), [&](int hole) {
           return std::find(ids.begin(), ids.end(), hole) != ids.end();
         });
}

GroupPlan plan_group(const Mesh& mesh, const std::vector<Hole>& holes, const LoopGroup& group,
                     const TriangulateOptions& options, const JoinOptions& join) {
  if (group.problem.failed()) {
    return {holes[group.holes[0]], PlannedTriangulation{std::nullopt, group.problem}};
  }
  if (group.holes.size() == 1) {
    return {holes[group.holes[0]], plan_triangulation(mesh, holes[group.holes[0]], options)};
  }
  std::vector<const Hole*> loops;
  for (const int id : group.holes) loops.push_back(&holes[id]);
  JoinedLoops joined = plan_joined_loops(mesh, loops, options, join);
  return {std::move(joined.polygon), std::move(joined.plan)};
}

}  // namespace holefill::detail
