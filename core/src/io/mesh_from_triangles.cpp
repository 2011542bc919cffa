#include "mesh_from_triangles.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <utility>

#include "../mesh_room.h"
#include "../parallel_indices.h"
#include "huge_pages.h"
#include "two_threads.h"

namespace holefill::io {
// A counting sort by the smaller vertex (stable: triangles in order), then each vertex's uses by
// the larger vertex: the order of sorting by (edge, triangle), in time linear in the triangles
// where a comparison sort of all uses was the largest cost of loading a big mesh. On several
// threads, each block of triangles is counted on its own and placed after the blocks before it
// in each vertex's run, so the uses are the same.
EdgeUses::EdgeUses(const std::vector<Triangle>& triangles, unsigned threads) {
  auto ends = [&triangles](std::size_t t, int c) {
    const auto a = static_cast<std::uint32_t>(triangles[t][c]);
    const auto b = static_cast<std::uint32_t>(triangles[t][(c + 1) % 3]);
    return std::pair{a, b};
  };
  const std::size_t parts = std::max(1u, threads), count = triangles.size();
  auto part_begin = [&](std::size_t p) { return count * p / parts; };
  std::vector<std::uint32_t> bound(parts, 0);
  detail::for_each_index(parts, threads, [&](std::size_t p) {
    for (std::size_t t = part_begin(p); t < part_begin(p + 1); ++t) {
      for (const int v : triangles[t])
        bound[p] = std::max(bound[p], static_cast<std::uint32_t>(v) + 1);
    }
  });
  const std::size_t vertices = *std::max_element(bound.begin(), bound.end());
  // Per block, its uses of each vertex v counted at v + 1, then turned into where they go.
  std::vector<std::vector<std::size_t>> next(parts);
  detail::for_each_index(parts, threads, [&](std::size_t p) {
    next[p] = huge_page_vector(vertices + 2, std::size_t{0});
    for (std::size_t t = part_begin(p); t < part_begin(p + 1); ++t) {
      for (int c = 0; c < 3; ++c) {
        const auto [a, b] = ends(t, c);
        ++next[p][std::min(a, b) + std::size_t{1}];
      }
    }
  });
  std::size_t placed = 0;
  for (std::size_t v = 0; v <= vertices; ++v) {
    for (std::size_t p = 0; p < parts; ++p) placed += std::exchange(next[p][v + 1], placed);
  }
  size_ = 3 * count;
  for (std::size_t first = 0; first < size_; first += std::size_t{1} << kBlockBits) {
    blocks_.push_back(huge_page_array<EdgeUse>(std::min(size_ - first, kBlockMask + 1)));
  }
  detail::for_each_index(parts, threads, [&](std::size_t p) {
    for (std::size_t t = part_begin(p); t < part_begin(p + 1); ++t) {
      for (int c = 0; c < 3; ++c) {
        const auto [a, b] = ends(t, c);
        (*this)[next[p][std::min(a, b) + std::size_t{1}]++] =
            EdgeUse(static_cast<int>(std::max(a, b)), static_cast<int>(t), a < b);
      }
    }
  });
  // The last block's counters end where each vertex's run ends: where the next one's starts.
  start_ = std::move(next.back());
  start_.pop_back();
  next.clear();
  const std::vector<std::size_t> part = vertex_parts(parts);
  detail::for_each_index(parts, threads,
                         [&](std::size_t p) { sort_runs_by_larger(part[p], part[p + 1]); });
}

std::vector<std::size_t> EdgeUses::vertex_parts(std::size_t parts) const {
  std::vector<std::size_t> first(parts + 1, vertex_bound());
  first[0] = 0;
  for (std::size_t p = 1; p < parts; ++p) {
    const auto at = std::lower_bound(start_.begin(), start_.end() - 1, size_ * p / parts);
    first[p] = std::max(first[p - 1], static_cast<std::size_t>(at - start_.begin()));
  }
  return first;
}

// Sorts each vertex's uses, already in triangle order, by the larger vertex: by insertion where a
// vertex has a few edges (stable, so ties stay in triangle order), else by the full order.
void EdgeUses::sort_runs_by_larger(std::size_t first_vertex, std::size_t last_vertex) {
  constexpr std::size_t kInsertionLimit = 32;
  auto before = [](const EdgeUse& a, const EdgeUse& b) {
    return a.larger() != b.larger() ? a.larger() < b.larger() : a.triangle() < b.triangle();
  };
  std::vector<EdgeUse> long_run;
  for (std::size_t v = first_vertex; v < last_vertex; ++v) {
    const std::size_t begin = start_[v], end = start_[v + 1];
    if (end - begin > kInsertionLimit) {
      long_run.clear();
      for (std::size_t i = begin; i < end; ++i) long_run.push_back((*this)[i]);
      std::sort(long_run.begin(), long_run.end(), before);
      for (std::size_t i = begin; i < end; ++i) (*this)[i] = long_run[i - begin];
      continue;
    }
    for (std::size_t i = begin + 1; i < end; ++i) {
      const EdgeUse u = (*this)[i];
      std::size_t j = i;
      for (; j > begin && u.larger() < (*this)[j - 1].larger(); --j) (*this)[j] = (*this)[j - 1];
      (*this)[j] = u;
    }
  }
}

void EdgeUses::release_before(std::size_t first) {
  for (std::size_t b = 0; b < blocks_.size() && (b + 1) << kBlockBits <= first; ++b) {
    blocks_[b].reset();
  }
}

namespace {

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

// The number of edges the uses describe.
std::size_t count_edges(const EdgeUses& uses) {
  std::size_t edges = 0;
  uses.for_each_edge([&edges](int, std::size_t, std::size_t) { ++edges; });
  return edges;
}

// The edges the mesh's arrays grow by at a time while the uses they come from are handed back.
constexpr std::size_t kEdgesAtATime = std::size_t{1} << 16;

// Where the mesh's edges grow to from e: kEdgesAtATime more, at most `edges`, moved back to the
// end of a huge page where one ends in between (a huge page is made resident whole: the array
// then holds none ahead of the uses handed back).
std::size_t next_edges_end(const Mesh& mesh, std::size_t e, std::size_t edges) {
  const std::size_t end = std::min(edges, e + kEdgesAtATime);
  const auto first = reinterpret_cast<std::uintptr_t>(&mesh.edge(EdgeHandle(0)));
  const std::size_t size = sizeof(mesh.edge(EdgeHandle(0)));
  const std::uintptr_t page_end = (first + end * size) & ~std::uintptr_t{kHugePageBytes - 1};
  const std::size_t before_page_end = page_end > first ? (page_end - first) / size : 0;
  return before_page_end > e ? before_page_end : end;
}

// Gives the mesh, whose vertices and faces are made, the edges of the uses, numbered in their
// order as OpenMesh numbers edges made in that order: edge e's first use (its lowest triangle)
// has halfedge 2 e, the other triangle on it 2 e + 1. Each halfedge gets its vertex and face, and
// a face's halfedges are chained through `next` from the face's halfedge (link_faces orders
// them). The mesh's edges grow as the uses are read, and the blocks of uses read are freed, so
// the two are never whole side by side.
void add_edges(Mesh& mesh, EdgeUses uses, std::size_t edges) {
  if (edges > 0) {  // the reserved array, on huge pages before it is written beyond its first edge
    mesh.resize(mesh.n_vertices(), 1, mesh.n_faces());
    prefer_huge_pages(&mesh.edge(EdgeHandle(0)), edges * sizeof(mesh.edge(EdgeHandle(0))));
  }
  std::size_t e = 0;
  uses.for_each_edge([&](int smaller, std::size_t first, std::size_t last) {
    if (e == mesh.n_edges()) {
      uses.release_before(first);
      mesh.resize(mesh.n_vertices(), next_edges_end(mesh, e, edges), mesh.n_faces());
    }
    const int larger = uses[first].larger();
    for (std::size_t k = first; k < last; ++k) {
      const EdgeUse& use = uses[k];
      const HalfedgeHandle h(static_cast<int>(2 * e + (k - first)));
      const VertexHandle from(use.forward() ? smaller : larger),
          to(use.forward() ? larger : smaller);
      mesh.set_vertex_handle(h, to);
      // The edge's first use also gives its other halfedge, which may have no face.
      if (k == first) mesh.set_vertex_handle(mesh.opposite_halfedge_handle(h), from);
      const FaceHandle f(use.triangle());
      mesh.set_face_handle(h, f);
      if (mesh.halfedge_handle(f).is_valid()) {
        mesh.set_next_halfedge_handle(h, mesh.halfedge_handle(f));
      }
      mesh.set_halfedge_handle(f, h);
    }
    ++e;
  });
}

// Which of a triangle's vertices, by index, is its first corner: 0 the smallest, 1 the middle, 2
// the largest (a byte a face, where the corners themselves took twelve beside the mesh).
std::uint8_t rank_of_first_corner(const Triangle& t) {
  return static_cast<std::uint8_t>((t[1] < t[0] ? 1 : 0) + (t[2] < t[0] ? 1 : 0));
}

// Links face t's three halfedges, chained by add_edges, in its triangle's order: corner c's
// halfedge runs from corner c to c + 1, corner 0 being the vertex of rank `first_corner_rank` of
// the face, and the face's halfedge arrives at corner 0 (as add_face makes it: the face
// circulators start there). Returns the halfedges from corner 0, 1, 2.
std::array<HalfedgeHandle, 3> link_face(Mesh& mesh, std::size_t t, std::uint8_t first_corner_rank) {
  const FaceHandle f(static_cast<int>(t));
  std::array<HalfedgeHandle, 3> h;
  h[0] = mesh.halfedge_handle(f);
  h[1] = mesh.next_halfedge_handle(h[0]);
  h[2] = mesh.next_halfedge_handle(h[1]);
  std::array<int, 3> from;
  for (int c = 0; c < 3; ++c) from[c] = mesh.from_vertex_handle(h[c]).idx();
  std::array<int, 3> by_index = from;
  std::sort(by_index.begin(), by_index.end());
  const int first = by_index[first_corner_rank];
  const auto at = std::find(from.begin(), from.end(), first) - from.begin();
  std::rotate(h.begin(), h.begin() + at, h.end());
  if (mesh.from_vertex_handle(h[1]) != mesh.to_vertex_handle(h[0])) std::swap(h[1], h[2]);
  mesh.set_halfedge_handle(f, h[2]);
  for (int c = 0; c < 3; ++c) mesh.set_next_halfedge_handle(h[c], h[(c + 1) % 3]);
  return h;
}

// Links every face (link_face). Each vertex gets the halfedge leaving it in the last triangle
// that uses it, as adding the faces in order would give it. On two threads (`two`), each links
// half of the faces (a face's halfedges are its own), the second half setting its vertices'
// halfedges as it goes; the first half's vertices are set afterwards, from its last face back,
// where no later face has set one.
void link_faces(Mesh& mesh, const std::vector<std::uint8_t>& first_corner_rank, bool two) {
  const std::size_t count = first_corner_rank.size(), middle = two ? count / 2 : 0;
  run_both(
      two,
      [&] {
        for (std::size_t t = 0; t < middle; ++t) link_face(mesh, t, first_corner_rank[t]);
      },
      [&] {
        for (std::size_t t = middle; t < count; ++t) {
          for (const auto h : link_face(mesh, t, first_corner_rank[t])) {
            mesh.set_halfedge_handle(mesh.from_vertex_handle(h), h);
          }
        }
      });
  for (std::size_t t = middle; t-- > 0;) {
    for (const auto h : mesh.fh_range(FaceHandle(static_cast<int>(t)))) {
      const VertexHandle from = mesh.from_vertex_handle(h);
      if (!mesh.halfedge_handle(from).is_valid()) mesh.set_halfedge_handle(from, h);
    }
  }
}

using detail::with_room;

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

// The identity 0, 1, ..., count - 1 (on huge pages).
std::vector<int> identity(std::size_t count) {
  std::vector<int> numbers = huge_page_vector(count, 0);
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

// Asks for huge pages under the first `count` values of each int and double property in
// [begin, end) (what the library's per-element properties hold), before they are written.
void prefer_huge_pages_for_properties(OpenMesh::BaseKernel::prop_iterator begin,
                                      OpenMesh::BaseKernel::prop_iterator end, std::size_t count) {
  for (auto property = begin; property != end; ++property) {
    if (auto* ints = dynamic_cast<OpenMesh::PropertyT<int>*>(*property)) {
      prefer_huge_pages(ints->data_vector().data(), count * sizeof(int));
    } else if (auto* doubles = dynamic_cast<OpenMesh::PropertyT<double>*>(*property)) {
      prefer_huge_pages(doubles->data_vector().data(), count * sizeof(double));
    }
  }
}

}  // namespace

std::size_t mesh_capacity(std::size_t count) { return with_room(count); }

void reserve_positions(std::vector<Point>& positions, std::size_t count, bool first_of_file) {
  reserve_on_huge_pages(positions, first_of_file ? mesh_capacity(count) : count, count);
}

// Faces that could not join the surface (an edge with a third face, a face turned against its
// neighbours) are kept, on their own copies of their corners, so no data is lost.
Mesh assemble(std::vector<Point> positions, std::vector<Triangle> triangles,
              std::vector<char> detached, std::size_t original_vertices, LoadReport& report,
              MeshSources* sources, EdgeUses uses, std::size_t two_threads_from,
              const std::function<void(Mesh&)>& add_properties) {
  if (sources) *sources = MeshSources();
  report.faces_detached = 0;
  if (std::find(detached.begin(), detached.end(), 1) != detached.end()) {
    if (sources) sources->vertex = identity(positions.size());
    triangles = detach(triangles, detached, positions, sources, report.faces_detached);
    // Detached triangles move to the end, on new vertices: the uses of the input are not theirs.
    uses = EdgeUses();
  }
  std::vector<char>().swap(detached);  // not held while the mesh's arrays grow
  const bool two = use_two_threads(triangles.size(), two_threads_from);
  if (uses.empty()) uses = EdgeUses(triangles, two ? 2 : 1);
  std::vector<std::uint8_t> first_corner_rank = huge_page_vector(triangles.size(), std::uint8_t{0});
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    first_corner_rank[t] = rank_of_first_corner(triangles[t]);
  }
  std::vector<Triangle>().swap(triangles);  // the uses and the ranks say the rest
  const std::size_t edges = count_edges(uses);
  Mesh mesh;
  if (add_properties) add_properties(mesh);
  mesh.reserve(with_room(positions.size()), with_room(edges), with_room(first_corner_rank.size()));
  prefer_huge_pages_for_properties(mesh.vprops_begin(), mesh.vprops_end(), positions.size());
  prefer_huge_pages_for_properties(mesh.hprops_begin(), mesh.hprops_end(), 2 * edges);
  prefer_huge_pages_for_properties(mesh.fprops_begin(), mesh.fprops_end(),
                                   first_corner_rank.size());
  add_vertices(mesh, positions);
  if (!first_corner_rank.empty()) {  // the faces' array too, on huge pages before it is written
    mesh.resize(mesh.n_vertices(), 0, 1);
    prefer_huge_pages(&mesh.face(FaceHandle(0)),
                      first_corner_rank.size() * sizeof(mesh.face(FaceHandle(0))));
  }
  mesh.resize(mesh.n_vertices(), 0, first_corner_rank.size());
  add_edges(mesh, std::move(uses), edges);
  link_faces(mesh, first_corner_rank, two);
  link_boundaries(mesh);
  for (std::size_t v = 0; v < original_vertices; ++v) {
    if (mesh.is_isolated(VertexHandle(static_cast<int>(v)))) ++report.isolated_vertices;
  }
  return mesh;
}

}  // namespace holefill::io
