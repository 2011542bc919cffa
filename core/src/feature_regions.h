// Refining and smoothing a patch region by region between its continued creases (feature_fill.h;
// internal, called by fill.cpp's stages when HoleFill::creases is not empty). Each region is a
// patch of its own whose boundary holds the crease chains: no crease edge is swapped, no crease
// vertex moves, and fairing sees only the surface on the region's own side of the creases and of
// the mesh's sharp edges, so that a plane stays planar and a cylinder cylindrical.
#pragma once

#include <functional>
#include <vector>

#include "holefill/fill.h"

namespace holefill::detail {

// The patch's regions: its faces grouped by connection across edges that are not crease edges,
// each as a Patch with those faces, the patch's new vertices inside it that lie on no crease,
// and every other vertex of its faces as its boundary. In the order of their first face.
std::vector<Patch> crease_regions(const Mesh& mesh, const Patch& patch,
                                  const std::vector<std::vector<VertexHandle>>& creases);

// refine_patch on each region, with the boundary scales of the whole patch and, on a crease
// vertex, the mean length of its crease edges; the new faces and vertices are added to `patch`.
// It enters phase::kRefiningBetweenCreases; once `progress` is cancelled it stops as
// refine_patch does, and the regions after are left as they are.
RefineResult refine_between_creases(Mesh& mesh, Patch& patch,
                                    const std::vector<std::vector<VertexHandle>>& creases,
                                    const RefineOptions& options,
                                    const Progress* progress = nullptr);

// The faces fairing may use around `region`: its own, and the mesh's faces reached from them
// within a few rings without crossing a crease edge or a sharp edge (features.h).
std::function<bool(FaceHandle)> same_side_faces(
    const Mesh& mesh, const Patch& region, const std::vector<std::vector<VertexHandle>>& creases,
    double angle_degrees, int rings);

}  // namespace holefill::detail
