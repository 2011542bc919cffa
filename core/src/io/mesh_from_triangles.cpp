#include "mesh_from_triangles.h"

#include <algorithm>
#include <numeric>

namespace holefill::io {
namespace {

// Sorts one vertex's uses, already in triangle order: by insertion where a vertex has a few
// edges (stable, so ties stay in triangle order), else by the full order.
void sort_run(std::vector<EdgeUse>::iterator begin, std::vector<EdgeUse>::iterator end) {
  constexpr std::ptrdiff_t kInsertionLimit = 32;
  if (end - begin > kInsertionLimit) {
    std::sort(begin, end);
    return;
  }
  for (auto i = begin + (begin != end ? 1 : 0); i < end; ++i) {
    const EdgeUse u = *i;
    auto j = i;
    for (; j > begin && u.edge() < (j - 1)->edge(); --j) *j = *(j - 1);
    *j = u;
  }
}

}  // namespace

// A counting sort by the smaller vertex (stable: triangles in order), then each vertex's uses by
// the larger vertex: the order of sorting by (edge, triangle), in time linear in the triangles
// where a comparison sort of all uses was the largest cost of loading a big mesh.
std::vector<EdgeUse> edge_uses(const std::vector<Triangle>& triangles) {
  auto use = [&triangles](int t, int c) -> EdgeUse {
    const auto a = static_cast<std::uint32_t>(triangles[t][c]);
    const auto b = static_cast<std::uint32_t>(triangles[t][(c + 1) % 3]);
    return {static_cast<std::uint64_t>(std::min(a, b)) << 32 | std::max(a, b), t, a < b};
  };
  std::uint32_t vertices = 0;
  for (const auto& triangle : triangles) {
    for (const int v : triangle) vertices = std::max(vertices, static_cast<std::uint32_t>(v) + 1);
  }
  std::vector<std::size_t> run_end(vertices + 1, 0);  // after the loop below: each run's start
  const int count = static_cast<int>(triangles.size());
  for (int t = 0; t < count; ++t) {
    for (int c = 0; c < 3; ++c) ++run_end[use(t, c).smaller() + 1];
  }
  for (std::uint32_t v = 0; v < vertices; ++v) run_end[v + 1] += run_end[v];
  std::vector<EdgeUse> uses(3 * triangles.size());
  for (int t = 0; t < count; ++t) {
    for (int c = 0; c < 3; ++c) {
      const EdgeUse u = use(t, c);
      uses[run_end[u.smaller()]++] = u;
    }
  }
  std::size_t begin = 0;
  for (std::uint32_t v = 0; v < vertices; ++v) {
    sort_run(uses.begin() + static_cast<std::ptrdiff_t>(begin),
             uses.begin() + static_cast<std::ptrdiff_t>(run_end[v]));
    begin = run_end[v];
  }
  return uses;
}

namespace {

// The corner of triangle `t` whose edge to the next corner is {a, b}.
int corner_of_edge(const Triangle& t, int a, int b) {
  for (int c = 0; c < 3; ++c) {
    const int from = t[c], to = t[(c + 1) % 3];
    if ((from == a && to == b) || (from == b && to == a)) return c;
  }
  return -1;
}

// At vertex x, the boundary halfedge leaving x on the same fan as the boundary halfedge
// `incoming` that arrives at x: turns around x through the fan's faces.
HalfedgeHandle fan_end(const Mesh& mesh, HalfedgeHandle incoming) {
  HalfedgeHandle out = mesh.opposite_halfedge_handle(
      mesh.prev_halfedge_handle(mesh.opposite_halfedge_handle(incoming)));
  while (!mesh.is_boundary(out)) {
    out = mesh.opposite_halfedge_handle(mesh.prev_halfedge_handle(out));
  }
  return out;
}

// Links the boundary halfedges: at each vertex, the boundary arriving at the end of one fan goes
// on along the boundary leaving the next fan (in the order the fans were met), so a vertex where
// open fans touch lies once per fan on one boundary loop, as OpenMesh's add_face links them.
void link_boundaries(Mesh& mesh) {
  struct Fan {
    int vertex;
    HalfedgeHandle in, out;
  };
  std::vector<Fan> fans;
  for (const auto h : mesh.halfedges()) {
    if (!mesh.is_boundary(h)) continue;
    fans.push_back({mesh.to_vertex_handle(h).idx(), h, fan_end(mesh, h)});
  }
  std::stable_sort(fans.begin(), fans.end(),
                   [](const Fan& a, const Fan& b) { return a.vertex < b.vertex; });
  for (std::size_t i = 0; i < fans.size();) {
    std::size_t j = i;
    while (j < fans.size() && fans[j].vertex == fans[i].vertex) ++j;
    for (std::size_t k = i; k < j; ++k) {
      mesh.set_next_halfedge_handle(fans[k].in, fans[k + 1 < j ? k + 1 : i].out);
    }
    mesh.set_halfedge_handle(VertexHandle(fans[i].vertex), fans[i].out);
    i = j;
  }
}

// The halfedges of the triangles' edges, numbered as OpenMesh numbers them when the edges are
// made in the order of their uses: edge e is made from its first use, whose halfedge is 2 e; the
// other triangle on the edge gets 2 e + 1. Computed before the mesh exists, so that the uses (12
// bytes each, three per triangle) are freed before the mesh's arrays are made.
struct HalfedgeNumbers {
  std::vector<int> of_corner;  // per corner 3 t + c: the halfedge from corner c to c + 1
  std::size_t edges = 0;
};

HalfedgeNumbers halfedge_numbers(const std::vector<Triangle>& triangles,
                                 std::vector<EdgeUse> known_uses) {
  const std::vector<EdgeUse> uses =
      known_uses.empty() ? edge_uses(triangles) : std::move(known_uses);
  HalfedgeNumbers numbers;
  numbers.of_corner.resize(3 * triangles.size());
  for_each_edge(uses, [&](std::size_t i, std::size_t j) {
    const int a = uses[i].smaller(), b = uses[i].larger();
    const int halfedge = 2 * static_cast<int>(numbers.edges++);
    for (std::size_t k = i; k < j; ++k) {
      const int t = uses[k].triangle();
      numbers.of_corner[3 * t + corner_of_edge(triangles[t], a, b)] = halfedge + (k == i ? 0 : 1);
    }
  });
  return numbers;
}

// Gives the mesh, whose vertices are made, the triangles' faces by building their half-edges
// directly: linear in the triangles, where add_face circulates around each corner (quadratic
// around a vertex with many fans). The edges and faces are made at once (as many new_edge and
// new_face calls would make them, each growing every property by one).
// Preconditions (what the repairs guarantee): every edge is used at most twice, in opposite
// directions, and a vertex has either one closed fan or only open ones.
void add_triangles(Mesh& mesh, const std::vector<Triangle>& triangles,
                   const HalfedgeNumbers& numbers) {
  mesh.resize(mesh.n_vertices(), numbers.edges, triangles.size());
  auto halfedge = [&numbers](std::size_t corner) {
    return HalfedgeHandle(numbers.of_corner[corner]);
  };
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const FaceHandle f(static_cast<int>(t));
    // As add_face does: the face circulators start at corner 0.
    mesh.set_halfedge_handle(f, halfedge(3 * t + 2));
    for (int c = 0; c < 3; ++c) {
      const HalfedgeHandle h = halfedge(3 * t + c);
      mesh.set_vertex_handle(h, VertexHandle(triangles[t][(c + 1) % 3]));
      // The edge's first use (2 e) also gives its other halfedge, which may have no face.
      if (h.idx() % 2 == 0) {
        mesh.set_vertex_handle(HalfedgeHandle(h.idx() + 1), VertexHandle(triangles[t][c]));
      }
      mesh.set_face_handle(h, f);
      mesh.set_next_halfedge_handle(h, halfedge(3 * t + (c + 1) % 3));
      mesh.set_halfedge_handle(mesh.from_vertex_handle(h), h);
    }
  }
  link_boundaries(mesh);
}

// Room for this many elements when there are `count`: an eighth more (see assemble).
std::size_t with_room(std::size_t count) { return count + count / 8 + 64; }

// The triangles with those marked in `detached` last, each on its own copies of its corners
// (appended to `positions`); says where the faces and the copies came from in `sources` (when
// given).
std::vector<Triangle> detach(const std::vector<Triangle>& triangles,
                             const std::vector<char>& detached, std::vector<Point>& positions,
                             MeshSources* sources, std::size_t& count) {
  std::vector<Triangle> kept, apart;
  std::vector<int> apart_source;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (!detached[t]) {
      kept.push_back(triangles[t]);
      if (sources) sources->face.push_back(static_cast<int>(t));
      continue;
    }
    Triangle copy;
    for (int c = 0; c < 3; ++c) {
      copy[c] = static_cast<int>(positions.size());
      const Point corner = positions[triangles[t][c]];
      positions.push_back(corner);
      if (sources) sources->vertex.push_back(triangles[t][c]);
    }
    apart.push_back(copy);
    apart_source.push_back(static_cast<int>(t));
  }
  if (sources) sources->face.insert(sources->face.end(), apart_source.begin(), apart_source.end());
  count = apart.size();
  kept.insert(kept.end(), apart.begin(), apart.end());
  return kept;
}

// The identity 0, 1, ..., count - 1.
std::vector<int> identity(std::size_t count) {
  std::vector<int> numbers(count);
  std::iota(numbers.begin(), numbers.end(), 0);
  return numbers;
}

// Gives the mesh its vertices at `positions`, which become its points array as they are (no
// copy held beside it), with the room the mesh was given.
void add_vertices(Mesh& mesh, std::vector<Point>& positions) {
  const std::size_t count = positions.size();
  positions.reserve(with_room(count));  // a copy only when the reader left no room
  mesh.property(mesh.points_pph()).data_vector().swap(positions);
  std::vector<Point>().swap(positions);
  mesh.resize(count, 0, 0);
}

}  // namespace

std::size_t mesh_capacity(std::size_t count) { return with_room(count); }

// Faces that could not join the surface (an edge with a third face, a face turned against its
// neighbours) are kept, on their own copies of their corners, so no data is lost.
Mesh assemble(std::vector<Point> positions, const std::vector<Triangle>& triangles,
              const std::vector<char>& detached, std::size_t original_vertices, LoadReport& report,
              MeshSources* sources, std::vector<EdgeUse> uses) {
  if (sources) {
    sources->vertex = identity(positions.size());
    sources->face.clear();
  }
  std::vector<Triangle> rearranged;  // only when some triangles are detached
  report.faces_detached = 0;
  if (std::find(detached.begin(), detached.end(), 1) != detached.end()) {
    rearranged = detach(triangles, detached, positions, sources, report.faces_detached);
    // Detached triangles move to the end, on new vertices: the uses of the input are not theirs.
    uses = std::vector<EdgeUse>();
  } else if (sources) {
    sources->face = identity(triangles.size());
  }
  const std::vector<Triangle>& kept = report.faces_detached ? rearranged : triangles;
  const HalfedgeNumbers numbers = halfedge_numbers(kept, std::move(uses));
  Mesh mesh;
  mesh.reserve(with_room(positions.size()), with_room(numbers.edges), with_room(kept.size()));
  add_vertices(mesh, positions);
  add_triangles(mesh, kept, numbers);
  for (std::size_t v = 0; v < original_vertices; ++v) {
    if (mesh.is_isolated(VertexHandle(static_cast<int>(v)))) ++report.isolated_vertices;
  }
  return mesh;
}

}  // namespace holefill::io
