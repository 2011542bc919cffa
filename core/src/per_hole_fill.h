// The per-hole pipeline of fill.cpp, for the code that runs it on many holes (fill_groups.cpp,
// patch_apart.cpp): one planned hole through every stage with its checks.
#pragma once

#include <chrono>
#include <vector>

#include "holefill/fill.h"
#include "holefill/loop_groups.h"
#include "mesh_face_index.h"

namespace holefill::detail {

// The seconds work() takes (the stages' times in HoleFill::times).
template <class Work>
double timed(Work&& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Runs the stages up to options.last_stage on `hole` (one loop, or loops joined into one polygon),
// with the triangulation already planned when `plan` is given, and the patch checked against the
// faces `index` holds when it is given (every face of the mesh outside the patch, as
// MeshFaceIndex promises), else against a scan of the mesh.
HoleFill fill_planned(Mesh& mesh, const Hole& hole, const FillOptions& options,
                      const PlannedTriangulation* plan, const MeshFaceIndex* index);

// The options for a group: loops joined by bridges are triangulated with constraints of their own
// (bridge.h), which the intersection avoidance's solves would not keep, so their plan stays.
FillOptions group_options(const LoopGroup& group, const FillOptions& options);

// fill_holes after the selection: every group planned and filled on options.threads threads,
// spliced into the mesh in order (patch_apart.h).
std::vector<HoleFill> fill_groups(Mesh& mesh, const std::vector<Hole>& holes,
                                  const std::vector<LoopGroup>& chosen, const FillOptions& options,
                                  Progress* progress);

}  // namespace holefill::detail
