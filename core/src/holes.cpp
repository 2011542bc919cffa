#include "holefill/holes.h"

#include <algorithm>
#include <unordered_map>

namespace holefill {

Hole hole_through(const Mesh& mesh, HalfedgeHandle start) {
  Hole hole;
  HalfedgeHandle h = start;
  // A loop can never be longer than the number of halfedges; the bound guards broken links.
  const std::size_t limit = mesh.n_halfedges();
  do {
    hole.halfedges.push_back(h);
    hole.vertices.push_back(mesh.from_vertex_handle(h));
    hole.perimeter += mesh.calc_edge_length(h);
    h = mesh.next_halfedge_handle(h);
  } while (h != start && hole.halfedges.size() <= limit);

  std::unordered_map<int, int> passes;
  Point sum(0.0, 0.0, 0.0);
  double surrounding_length = 0.0;
  std::size_t surrounding_count = 0;
  for (const auto v : hole.vertices) {
    sum += mesh.point(v);
    // A vertex the loop passes many times (a pinch of many fans) has its edges counted once:
    // counting them at every pass made the loop quadratic in its passes.
    if (++passes[v.idx()] > 1) {
      if (passes[v.idx()] == 2) ++hole.repeated_vertices;
      continue;
    }
    for (const auto e : mesh.ve_range(v)) {
      surrounding_length += mesh.calc_edge_length(e);
      ++surrounding_count;
    }
  }
  hole.centroid = sum / static_cast<double>(hole.vertices.size());
  hole.mean_surrounding_edge_length =
      surrounding_count ? surrounding_length / static_cast<double>(surrounding_count) : 0.0;
  return hole;
}

std::vector<Hole> find_holes(const Mesh& mesh) {
  std::vector<Hole> holes;
  std::vector<bool> visited(mesh.n_halfedges(), false);
  for (const auto h : mesh.halfedges()) {
    if (visited[h.idx()] || !mesh.is_boundary(h) || mesh.status(h).deleted()) continue;
    Hole hole = hole_through(mesh, h);
    for (const auto loop_h : hole.halfedges) visited[loop_h.idx()] = true;
    holes.push_back(std::move(hole));
  }

  std::unordered_map<int, int> loops_at_vertex;
  for (const auto& hole : holes) {
    for (const auto v : hole.vertices) ++loops_at_vertex[v.idx()];
  }
  for (auto& hole : holes) {
    hole.pinched = std::any_of(hole.vertices.begin(), hole.vertices.end(),
                               [&](VertexHandle v) { return loops_at_vertex[v.idx()] > 1; });
  }

  std::stable_sort(holes.begin(), holes.end(),
                   [](const Hole& a, const Hole& b) { return a.size() > b.size(); });
  for (std::size_t i = 0; i < holes.size(); ++i) holes[i].id = static_cast<int>(i);
  return holes;
}

}  // namespace holefill
