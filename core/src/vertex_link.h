// The link of a vertex v: each face (v, a, b) around it, in its orientation, is the link edge
// a -> b between two neighbours. v is manifold, and its faces consistently oriented, exactly when
// its link is one path (v on a border) or one cycle (v inside). Stitching and pinch filling ask
// this of a vertex before they change the faces around it.
#pragma once

#include <unordered_map>
#include <utility>
#include <vector>

#include "holefill/mesh.h"

namespace holefill::detail {

// Whether the link edges form one path, or one cycle of at least three edges (two faces
// (v, a, b) and (v, b, a) would be one face twice), with no neighbour left or entered twice.
inline bool is_one_fan(const std::vector<std::pair<int, int>>& link) {
  std::unordered_map<int, int> next, previous;
  for (const auto& [a, b] : link) {
    if (a == b || !next.emplace(a, b).second || !previous.emplace(b, a).second) return false;
  }
  int start = next.empty() ? -1 : next.begin()->first;
  int path_starts = 0;
  for (const auto& [a, b] : next) {
    if (!previous.count(a)) {
      start = a;
      ++path_starts;
    }
  }
  if (path_starts > 1) return false;
  std::size_t walked = 0;
  for (int at = start;;) {
    const auto step = next.find(at);
    if (step == next.end()) break;
    ++walked;
    at = step->second;
    if (at == start) break;
  }
  return walked == link.size() && (path_starts == 1 || walked >= 3);
}

// The link edges of v's faces in the mesh, neighbours renamed by `name` (a vertex index ->
// the index it stands for).
template <class Rename>
void add_link_edges(const Mesh& mesh, VertexHandle v, Rename&& name,
                    std::vector<std::pair<int, int>>& link) {
  for (const auto h : mesh.voh_range(v)) {
    if (mesh.is_boundary(h)) continue;
    link.emplace_back(name(mesh.to_vertex_handle(h).idx()),
                      name(mesh.to_vertex_handle(mesh.next_halfedge_handle(h)).idx()));
  }
}

}  // namespace holefill::detail
