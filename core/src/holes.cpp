#include "holefill/holes.h"

#include <algorithm>
#include <array>
#include <optional>
#include <unordered_map>
#include <unordered_set>

#include "coincident_vertices.h"
#include "deletion_flags.h"

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

namespace {

// The out-going boundary halfedge that ends the fan of faces around v which starts at boundary
// halfedge `in` (u -> v): the faces are walked from in's opposite across the edges at v. Invalid
// when the walk does not end (broken links).
HalfedgeHandle fan_end(const Mesh& mesh, HalfedgeHandle in) {
  HalfedgeHandle out = mesh.opposite_halfedge_handle(in);  // v -> u, in the fan's first face
  for (std::size_t step = 0; step <= mesh.n_halfedges(); ++step) {
    const HalfedgeHandle next_out = mesh.opposite_halfedge_handle(mesh.prev_halfedge_handle(out));
    if (mesh.is_boundary(next_out)) return next_out;
    out = next_out;
  }
  return HalfedgeHandle();
}

// Splits `hole` at its first vertex passed several times whose stretches are all gaps; true when
// it did.
bool separate_at_a_pinch(Mesh& mesh, const Hole& hole) {
  std::unordered_map<int, std::vector<std::size_t>> passes;
  for (std::size_t i = 0; i < hole.size(); ++i) passes[hole.vertices[i].idx()].push_back(i);
  for (std::size_t i = 0; i < hole.size(); ++i) {
    const std::vector<std::size_t>& at = passes[hole.vertices[i].idx()];
    if (at.size() < 2 || at.front() != i) continue;
    // Stretch j runs from halfedge at[j] (out of the vertex) to the one before at[j + 1] (into it).
    auto last_of = [&](std::size_t j) {
      return hole.halfedges[(at[(j + 1) % at.size()] + hole.size() - 1) % hole.size()];
    };
    bool all_gaps = true;
    for (std::size_t j = 0; j < at.size() && all_gaps; ++j) {
      all_gaps = fan_end(mesh, last_of(j)) != hole.halfedges[at[j]];
    }
    if (!all_gaps) continue;
    for (std::size_t j = 0; j < at.size(); ++j) {
      mesh.set_next_halfedge_handle(last_of(j), hole.halfedges[at[j]]);
    }
    return true;
  }
  return false;
}

}  // namespace

std::size_t separate_touching_holes(Mesh& mesh, const std::vector<Hole>& holes) {
  std::size_t added = 0;
  std::vector<Hole> work;
  for (const auto& hole : holes) {
    if (hole.repeated_vertices > 0) work.push_back(hole);
  }
  while (!work.empty()) {
    const Hole hole = std::move(work.back());
    work.pop_back();
    if (hole.repeated_vertices == 0 || !separate_at_a_pinch(mesh, hole)) continue;
    // The loop fell apart into one loop per stretch: look at each again (another vertex of it
    // may be passed twice too).
    const std::size_t before = work.size();
    std::unordered_set<int> seen;
    for (const auto h : hole.halfedges) {
      if (seen.count(h.idx())) continue;
      Hole piece = hole_through(mesh, h);
      for (const auto piece_h : piece.halfedges) seen.insert(piece_h.idx());
      work.push_back(std::move(piece));
    }
    added += work.size() - before - 1;
  }
  return added;
}

namespace {

// find_holes' flags, order and ids for `holes`, the loops each described from its lowest halfedge
// index and listed in the order of those indices.
std::vector<Hole> as_found(std::vector<Hole> holes) {
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

}  // namespace

std::vector<Hole> find_holes(const Mesh& mesh) {
  std::vector<Hole> holes;
  std::vector<bool> visited(mesh.n_halfedges(), false);
  for (const auto h : mesh.halfedges()) {
    if (visited[h.idx()] || !mesh.is_boundary(h) || detail::is_deleted(mesh, h)) continue;
    Hole hole = hole_through(mesh, h);
    for (const auto loop_h : hole.halfedges) visited[loop_h.idx()] = true;
    holes.push_back(std::move(hole));
  }
  return as_found(std::move(holes));
}

// Separation relinks only the loops that pass a vertex more than once, within each: the others
// are kept as found, and those are walked again from their lowest halfedges, as the scan of
// find_holes would meet them.
std::vector<Hole> find_separated_holes(Mesh& mesh) {
  return separated_holes(mesh, find_holes(mesh));
}

std::vector<Hole> separated_holes(Mesh& mesh, std::vector<Hole> holes) {
  if (separate_touching_holes(mesh, holes) == 0) return holes;
  std::vector<Hole> loops;
  for (Hole& hole : holes) {
    if (hole.repeated_vertices == 0) {
      loops.push_back(std::move(hole));
      continue;
    }
    std::vector<HalfedgeHandle> halfedges = hole.halfedges;
    std::sort(halfedges.begin(), halfedges.end());
    std::unordered_set<int> walked;
    for (const auto h : halfedges) {
      if (walked.count(h.idx())) continue;
      Hole piece = hole_through(mesh, h);
      for (const auto piece_h : piece.halfedges) walked.insert(piece_h.idx());
      loops.push_back(std::move(piece));
    }
  }
  std::sort(loops.begin(), loops.end(),
            [](const Hole& a, const Hole& b) { return a.halfedges.front() < b.halfedges.front(); });
  return as_found(std::move(loops));
}

std::size_t count_holes(const Mesh& mesh) {
  std::size_t loops = 0;
  std::vector<bool> visited(mesh.n_halfedges(), false);
  const std::size_t limit = mesh.n_halfedges();  // as hole_through bounds a broken loop
  for (const auto h : mesh.halfedges()) {
    if (visited[h.idx()] || !mesh.is_boundary(h) || detail::is_deleted(mesh, h)) continue;
    ++loops;
    HalfedgeHandle at = h;
    std::size_t length = 0;
    do {
      visited[at.idx()] = true;
      at = mesh.next_halfedge_handle(at);
    } while (at != h && ++length <= limit);
  }
  return loops;
}

bool is_boundary_loop(const Mesh& mesh, const Hole& hole) {
  const std::size_t n = hole.halfedges.size();
  if (n == 0 || hole.vertices.size() != n) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const HalfedgeHandle h = hole.halfedges[i];
    if (!h.is_valid() || static_cast<std::size_t>(h.idx()) >= mesh.n_halfedges() ||
        !mesh.is_boundary(h) || mesh.from_vertex_handle(h) != hole.vertices[i] ||
        mesh.to_vertex_handle(h) != hole.vertices[(i + 1) % n]) {
      return false;
    }
  }
  return true;
}

namespace detail {

std::optional<std::pair<int, int>> coincident_vertices(const Mesh& mesh, const Hole& hole) {
  std::vector<std::pair<std::array<double, 3>, int>> at;
  for (const auto v : hole.vertices) {
    const Point& p = mesh.point(v);
    at.push_back({{p[0], p[1], p[2]}, v.idx()});
  }
  std::sort(at.begin(), at.end());
  for (std::size_t i = 1; i < at.size(); ++i) {
    if (at[i].first == at[i - 1].first && at[i].second != at[i - 1].second) {
      return std::pair<int, int>(std::min(at[i].second, at[i - 1].second),
                                 std::max(at[i].second, at[i - 1].second));
    }
  }
  return std::nullopt;
}

}  // namespace detail

}  // namespace holefill
