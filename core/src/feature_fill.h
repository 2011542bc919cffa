// Filling a hole along its continued sharp features (features.h; internal, called by fill.cpp):
// vertices are placed along each continued crease and corner path, the paths split the hole's
// loop into sub-loops, and each sub-loop is triangulated on its own by the dynamic program of
// triangulate.h. The paths' edges are the creases of the patch: refinement and smoothing then work
// region by region between them (feature_regions.h), so each face of the part continues its own
// shape and the crease stays sharp.
#pragma once

#include <string>
#include <vector>

#include "holefill/features.h"
#include "holefill/fill.h"
#include "mesh_face_index.h"

namespace holefill::detail {

// The hole's sub-loops: the loop's positions 0 .. n-1 and the new points n, n+1, ... (the
// junctions' paths in order, then the corner points), each sub-loop oriented as the hole.
struct FeatureLoops {
  std::vector<Point> new_points;
  std::vector<std::vector<int>> loops;
  // Each continued path as nodes from its entry to its other entry or its corner point.
  std::vector<std::vector<int>> chains;
  std::string failure;  // why the paths do not split the hole into loops
};

// Splits the hole's loop along the junctions' paths (features.continued() must hold).
FeatureLoops split_along_features(const Mesh& mesh, const Hole& hole, const HoleFeatures& features);

// The triangulate stage for a hole with continued features: finds them (options.features), and
// when every line is matched adds a patch triangulated sub-loop by sub-loop, with vertices along
// the paths (fill.patch.new_vertices; fill.creases holds the paths as vertex chains). True when
// that patch was added; false otherwise, the mesh unchanged, with fill.features_note saying why
// when feature lines were found (no partner, a path not splitting the hole, no clean
// triangulation, a patch cutting the mesh). fill.features holds what was found either way.
bool feature_triangulate_stage(Mesh& mesh, const Hole& hole, HoleFill& fill,
                               const FillOptions& options, const MeshFaceIndex* index);

}  // namespace holefill::detail
