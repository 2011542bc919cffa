// Moving the corners of faces onto other vertices (stitch.cpp's seams and weld.cpp's touching
// vertices merged, weld.cpp's pinches split again): the groups to merge, and the move itself, which
// keeps every face's index, corners' order and properties.
#pragma once

#include <algorithm>
#include <functional>
#include <numeric>
#include <vector>

#include "holefill/mesh.h"

namespace holefill::detail {

// Groups of vertices to merge; each group's root is its lowest index, the vertex kept.
class VertexGroups {
 public:
  explicit VertexGroups(std::size_t n) : parent_(n) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  int root(int v) {
    while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];
    return v;
  }
  void join(int a, int b) {
    a = root(a);
    b = root(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<int> parent_;
};

// The vertex a face's corner goes to: corner_of(face, vertex it is on now).
using CornerMap = std::function<VertexHandle(FaceHandle, VertexHandle)>;

// Puts the corners of `faces` (any order, repeats allowed) on the vertices `corner_of` names and
// removes `unused` (vertices no face keeps), then collects the garbage. The faces are deleted and
// added again, highest index first, so that garbage collection puts each back at its index, with
// its first corner, its properties and its halfedges'; an edge it makes anew gets the old one's.
// Other vertices keep their order (indices shift down past removed ones). False, with the mesh as
// it was, when OpenMesh refuses a face. Expects a mesh without deleted elements.
bool move_corners(Mesh& mesh, std::vector<FaceHandle> faces, const CornerMap& corner_of,
                  const std::vector<VertexHandle>& unused = {});

// Merges every vertex into kept_of[vertex] (move_corners): false, with the mesh as it was, when
// OpenMesh refuses a face.
bool merge_vertices(Mesh& mesh, const std::vector<int>& kept_of);

}  // namespace holefill::detail
