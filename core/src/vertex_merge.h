// Merging vertices of a mesh into others (stitch.cpp's seams, weld.cpp's touching vertices): the
// groups to merge, and the merge itself, which keeps every face's index, corners' order and
// properties.
#pragma once

#include <algorithm>
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

// Merges every vertex into kept_of[vertex]: the faces of merged vertices are deleted and added
// again on the kept ones, highest index first, so that garbage collection puts each back at its
// index. False, with the mesh as it was, when OpenMesh refuses a face.
bool merge_vertices(Mesh& mesh, const std::vector<int>& kept_of);

}  // namespace holefill::detail
