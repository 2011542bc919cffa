// advance_joined() without its scaling, for callers that run many steps on one mesh
// (fill_sequence.cpp) and have checked once that the mesh needs none.
#pragma once

#include <vector>

#include "holefill/fill.h"
#include "mesh_face_index.h"

namespace holefill::detail {

// advance_joined(mesh, loops, fill, options) on a mesh that SafeScale would leave as it is. The
// patch is checked against the faces `index` holds (when given: it must hold every face of the
// mesh outside this patch, as MeshFaceIndex promises) instead of a scan of the mesh.
StageRun advance_unscaled(Mesh& mesh, const std::vector<const Hole*>& loops, HoleFill& fill,
                          const FillOptions& options, const MeshFaceIndex* index);

}  // namespace holefill::detail
