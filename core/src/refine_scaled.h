// refine_patch without its first step (internal): for callers that set the vertices' scales
// themselves (feature_regions.cpp, whose regions' boundaries hold new crease vertices).
#pragma once

#include "holefill/refine.h"

namespace holefill::detail {

// refine_patch(mesh, patch, options) with the scale sigma (PatchTags::scale) of every vertex of
// the patch's faces already assigned, instead of assign_boundary_scales's.
RefineResult refine_with_scales(Mesh& mesh, Patch& patch, const RefineOptions& options,
                                const Progress* progress = nullptr);

}  // namespace holefill::detail
