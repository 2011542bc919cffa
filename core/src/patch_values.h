// Values for a patch's new elements from the mesh around it, shared by the attributes of every
// kind (attributes.h, obj_attributes.h): harmonic interpolation over the patch and the majority
// of the faces along the hole.
#pragma once

#include <algorithm>
#include <map>
#include <vector>

#include "holefill/mesh.h"
#include "holefill/patch.h"

namespace holefill::detail {

// Harmonic values on the patch's new vertices (the umbrella operator's fixed point): every other
// vertex of the patch keeps its value. Gauss-Seidel sweeps from the mean of the boundary.
void interpolate_harmonically(Mesh& mesh, const Patch& patch,
                              const std::vector<OpenMesh::VPropHandleT<double>>& scalars);

// Sets every patch face's `property` to the value most original faces along the hole have (ties:
// the smallest). Leaves them as they are when no original face borders the hole.
template <class T>
void take_majority_along_hole(Mesh& mesh, const Patch& patch, OpenMesh::FPropHandleT<T> property) {
  std::map<T, int> votes;
  for (std::size_t i = 0; i < patch.boundary.size(); ++i) {
    const VertexHandle from = patch.boundary[i];
    const VertexHandle to = patch.boundary[(i + 1) % patch.boundary.size()];
    const HalfedgeHandle h = mesh.find_halfedge(from, to);
    if (!h.is_valid()) continue;
    for (const auto side : {h, mesh.opposite_halfedge_handle(h)}) {
      const FaceHandle face = mesh.face_handle(side);
      if (face.is_valid() && face_stage(mesh, face) == Stage::Original) {
        ++votes[mesh.property(property, face)];
      }
    }
  }
  if (votes.empty()) return;
  const auto winner = std::max_element(
      votes.begin(), votes.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  for (const auto f : patch.faces) mesh.property(property, f) = winner->first;
}

}  // namespace holefill::detail
