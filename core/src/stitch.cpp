#include "holefill/stitch.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <optional>
#include <span>
#include <unordered_map>
#include <vector>

#include "available_cores.h"
#include "boundary_points.h"
#include "parallel_indices.h"
#include "t_junctions.h"
#include "vertex_link.h"
#include "vertex_merge.h"

namespace holefill {
namespace {

using detail::BoundaryPoints;
using detail::merge_vertices;
using detail::VertexGroups;

double default_tolerance(const Mesh& mesh) {
  Point low(INFINITY, INFINITY, INFINITY), high(-INFINITY, -INFINITY, -INFINITY);
  for (const auto v : mesh.vertices()) {
    low.minimize(mesh.point(v));
    high.maximize(mesh.point(v));
  }
  return mesh.n_vertices() ? kDefaultStitchRelativeTolerance * (high - low).norm() : 0.0;
}

// Lists of integers, one per key 0 .. n-1, in two flat arrays (compressed rows): the stitch
// keeps one per boundary point of a mesh that may have millions, where a vector each would cost
// an allocation each.
struct FlatLists {
  std::vector<std::uint32_t> start;  // list i is items[start[i] .. start[i + 1])
  std::vector<int> items;
  std::span<const int> operator[](std::size_t i) const {
    return {items.data() + start[i], items.data() + start[i + 1]};
  }
};

// Builds FlatLists from (key, item) pairs, items in the order given.
FlatLists flat_lists(std::size_t keys, const std::vector<std::pair<int, int>>& pairs) {
  FlatLists lists;
  lists.start.assign(keys + 1, 0);
  for (const auto& [key, item] : pairs) ++lists.start[static_cast<std::size_t>(key) + 1];
  for (std::size_t k = 0; k < keys; ++k) lists.start[k + 1] += lists.start[k];
  lists.items.resize(pairs.size());
  std::vector<std::uint32_t> next(lists.start.begin(), lists.start.end() - 1);
  for (const auto& [key, item] : pairs) lists.items[next[static_cast<std::size_t>(key)]++] = item;
  return lists;
}

// For each point, the points within `tolerance` of it (itself included), as point indices; a
// point with more than kMostPointsWithin such points is crowded (`crowded` says so) and lists
// only itself. The search stops at the kMostPointsWithin + 1st: a tolerance far above the edge
// length (1e10 on a grid of face-by-face squares) listed every point for every point, 154 s and
// 19 GB for 60,000 faces.
FlatLists points_within(const detail::BoundaryIndex& index, double tolerance,
                        std::vector<char>& crowded, unsigned threads) {
  const BoundaryPoints& points = index.points;
  const std::size_t n = points.vertices.size();
  crowded.assign(n, 0);
  // The points in blocks on `threads` threads, each block's pairs in its points' order, the
  // blocks then joined in order: the lists of one thread.
  constexpr std::size_t kBlock = std::size_t{1} << 13;
  std::vector<std::vector<std::pair<int, int>>> block_pairs((n + kBlock - 1) / kBlock);
  detail::for_each_index(block_pairs.size(), threads, [&](std::size_t block) {
    std::vector<std::size_t> found;
    std::vector<int> within;
    auto& pairs = block_pairs[block];
    for (std::size_t s = block * kBlock; s < std::min(n, (block + 1) * kBlock); ++s) {
      const Point& at = points.mesh.point(points.vertices[s]);
      within.clear();
      if (detail::points_within_tolerance(index, at, tolerance, kMostPointsWithin, found)) {
        for (const std::size_t k : found) within.push_back(static_cast<int>(k));
      } else {
        crowded[s] = 1;
        within.assign(1, static_cast<int>(s));
      }
      std::sort(within.begin(), within.end());  // the order of the point list, whatever the tree's
      for (const int other : within) pairs.emplace_back(static_cast<int>(s), other);
    }
  });
  std::size_t total = 0;
  for (const auto& pairs : block_pairs) total += pairs.size();
  std::vector<std::pair<int, int>> pairs;
  pairs.reserve(total);
  for (auto& block : block_pairs) {
    pairs.insert(pairs.end(), block.begin(), block.end());
    std::vector<std::pair<int, int>>().swap(block);
  }
  return flat_lists(n, pairs);
}

// Boundary halfedges a->b and b'->a' with a' within the tolerance of a and b' of b, each listed
// once (lower index first). A halfedge that lies on more than one other is matched with none:
// three or more sheets meet there, and joining any two of them would be a guess.
struct Matches {
  std::vector<std::pair<HalfedgeHandle, HalfedgeHandle>> pairs;
  std::size_t halfedges_on_another = 0;  // boundary halfedges lying on at least one other
  std::vector<int> on_another;           // those halfedges, in increasing order
};

// A vertex with more boundary halfedges leaving it than this (a pinch of many fans) has its
// partners looked up by their ends rather than scanned, which would be quadratic in the fans.
constexpr std::size_t kScanLimit = 16;

Matches matching_boundary_edges(const Mesh& mesh, const detail::BoundaryIndex& index,
                                double tolerance, unsigned threads) {
  const BoundaryPoints& points = index.points;
  std::vector<int> slot(mesh.n_vertices(), -1);
  for (std::size_t s = 0; s < points.vertices.size(); ++s) {
    slot[points.vertices[s].idx()] = static_cast<int>(s);
  }
  Matches matches;
  if (points.vertices.empty()) return matches;
  // Every boundary vertex is the end of a boundary halfedge, so both ends of one have a slot.
  auto ends_key = [](int from_slot, int to_slot) {
    return (static_cast<std::uint64_t>(from_slot) << 32) | static_cast<std::uint32_t>(to_slot);
  };
  // The boundary halfedges in increasing order, those leaving each point, and all of them sorted
  // by their ends: the arrays below are per boundary halfedge, not per halfedge of the mesh.
  std::vector<int> boundary;
  std::vector<std::pair<int, int>> leaving;
  std::vector<std::pair<std::uint64_t, int>> by_ends;
  for (const auto h : mesh.halfedges()) {
    if (!mesh.is_boundary(h)) continue;
    boundary.push_back(h.idx());
    const int from = slot[mesh.from_vertex_handle(h).idx()],
              to = slot[mesh.to_vertex_handle(h).idx()];
    leaving.emplace_back(from, h.idx());
    by_ends.emplace_back(ends_key(from, to), h.idx());
  }
  const FlatLists out_of = flat_lists(points.vertices.size(), leaving);
  std::sort(by_ends.begin(), by_ends.end());
  std::vector<char> crowded;
  const FlatLists near = points_within(index, tolerance, crowded, threads);

  std::vector<int> match_of(boundary.size(), -1);  // per boundary halfedge
  std::vector<char> near_p(points.vertices.size(), 0);
  for (std::size_t b = 0; b < boundary.size(); ++b) {
    const HalfedgeHandle h(boundary[b]);
    const int p = slot[mesh.from_vertex_handle(h).idx()], q = slot[mesh.to_vertex_handle(h).idx()];
    if (crowded[p] || crowded[q]) {  // too many candidates to choose from: left apart
      match_of[b] = -2;
      ++matches.halfedges_on_another;
      continue;
    }
    int count = 0;
    auto found = [&](int other) {
      if (other != h.idx()) match_of[b] = count++ ? -2 : other;
    };
    for (const int p2 : near[p]) near_p[p2] = 1;
    for (const int q2 : near[q]) {
      const auto leaving_q2 = out_of[q2];
      if (leaving_q2.size() <= kScanLimit) {
        for (const int other : leaving_q2) {
          if (near_p[slot[mesh.to_vertex_handle(HalfedgeHandle(other)).idx()]]) found(other);
        }
        continue;
      }
      for (const int p2 : near[p]) {
        const std::uint64_t key = ends_key(q2, p2);
        auto at = std::lower_bound(by_ends.begin(), by_ends.end(), std::make_pair(key, -1));
        for (; at != by_ends.end() && at->first == key; ++at) found(at->second);
      }
    }
    for (const int p2 : near[p]) near_p[p2] = 0;
    if (count > 0) ++matches.halfedges_on_another;
  }
  for (std::size_t b = 0; b < boundary.size(); ++b) {
    if (match_of[b] != -1) matches.on_another.push_back(boundary[b]);
    const int h = boundary[b], other = match_of[b];
    if (other <= h) continue;
    const auto at = std::lower_bound(boundary.begin(), boundary.end(), other);
    if (match_of[static_cast<std::size_t>(at - boundary.begin())] == h) {
      matches.pairs.emplace_back(HalfedgeHandle(h), HalfedgeHandle(other));
    }
  }
  return matches;
}

// Whether merging `members` into `kept` (kept_of maps every vertex to the vertex it becomes)
// leaves `kept` one fan of consistently oriented faces (vertex_link.h), with no face collapsed
// and every member within the tolerance.
bool merge_is_clean(const Mesh& mesh, VertexHandle kept, const std::vector<VertexHandle>& members,
                    const std::vector<int>& kept_of, double tolerance) {
  std::vector<std::pair<int, int>> link;
  for (const auto v : members) {
    if ((mesh.point(v) - mesh.point(kept)).norm() > tolerance) return false;
    detail::add_link_edges(
        mesh, v, [&](int u) { return kept_of[u]; }, link);
  }
  for (const auto& [a, b] : link) {
    if (a == kept.idx() || b == kept.idx()) return false;  // a face would lose a corner
  }
  return detail::is_one_fan(link);
}

// Stitches the boundary edges that lie on each other end to end (stitch_borders without the
// T-junctions); `matches` are the mesh's as it is now.
StitchReport stitch_matching_edges(Mesh& mesh, const Matches& matches, double tolerance) {
  StitchReport report;
  report.tolerance = tolerance;
  std::vector<std::pair<HalfedgeHandle, HalfedgeHandle>> pairs = matches.pairs;

  // Join the ends of every pair; a group whose merge would not be clean gives up its pairs, and
  // the groups are formed again, until every group is clean.
  std::vector<int> kept_of;
  for (bool changed = !pairs.empty(); changed;) {  // no pairs: no per-vertex arrays either
    changed = false;
    VertexGroups groups(mesh.n_vertices());
    for (const auto& [a, b] : pairs) {
      groups.join(mesh.from_vertex_handle(a).idx(), mesh.to_vertex_handle(b).idx());
      groups.join(mesh.to_vertex_handle(a).idx(), mesh.from_vertex_handle(b).idx());
    }
    kept_of.assign(mesh.n_vertices(), 0);
    std::unordered_map<int, std::vector<VertexHandle>> members;
    for (const auto v : mesh.vertices()) {
      kept_of[v.idx()] = groups.root(v.idx());
      if (kept_of[v.idx()] != v.idx()) members[kept_of[v.idx()]].push_back(v);
    }
    std::vector<char> refused(mesh.n_vertices(), 0);
    for (const auto& [kept, group] : members) {
      std::vector<VertexHandle> all = group;
      all.push_back(VertexHandle(kept));
      if (!merge_is_clean(mesh, VertexHandle(kept), all, kept_of, report.tolerance)) {
        refused[kept] = 1;
      }
    }
    const auto before = pairs.size();
    std::erase_if(pairs, [&](const auto& pair) {
      return refused[kept_of[mesh.from_vertex_handle(pair.first).idx()]] ||
             refused[kept_of[mesh.to_vertex_handle(pair.first).idx()]];
    });
    changed = pairs.size() != before;
  }
  report.edges_left_apart = matches.halfedges_on_another - 2 * pairs.size();
  if (pairs.empty()) return report;

  VertexGroups seams(mesh.n_vertices());
  for (const auto& [a, b] : pairs) {
    seams.join(kept_of[mesh.from_vertex_handle(a).idx()], kept_of[mesh.to_vertex_handle(a).idx()]);
  }
  std::vector<char> seam_seen(mesh.n_vertices(), 0);
  for (const auto& [a, b] : pairs) {
    const int seam = seams.root(kept_of[mesh.from_vertex_handle(a).idx()]);
    if (!seam_seen[seam]) ++report.seams, seam_seen[seam] = 1;
  }
  for (const auto v : mesh.vertices()) {
    if (kept_of[v.idx()] == v.idx()) continue;
    ++report.vertices_merged;
    report.largest_distance =
        std::max(report.largest_distance,
                 (mesh.point(v) - mesh.point(VertexHandle(kept_of[v.idx()]))).norm());
  }
  if (!merge_vertices(mesh, kept_of)) {
    report.edges_left_apart = matches.halfedges_on_another;
    report.vertices_merged = 0;
    report.largest_distance = 0.0;
    report.seams = 0;
    return report;
  }
  report.edges_stitched = pairs.size();
  return report;
}

// Splits the edges at `junctions` on a copy of the mesh and stitches the copy. When every new
// vertex was merged into its junction's vertex, the copy replaces the mesh and the report is
// returned; otherwise the mesh is left as it was and the junctions whose vertices were left
// over are removed from the list.
std::optional<StitchReport> stitch_with_junctions(Mesh& mesh, double tolerance, unsigned threads,
                                                  std::vector<detail::TJunction>& junctions) {
  Mesh trial = mesh;
  OpenMesh::VPropHandleT<int> junction_of;  // 1 + the junction a new vertex stands for
  trial.add_property(junction_of);
  const std::vector<VertexHandle> added = detail::split_at_t_junctions(trial, junctions);
  for (std::size_t j = 0; j < added.size(); ++j) {
    trial.property(junction_of, added[j]) = static_cast<int>(j) + 1;
  }
  StitchReport report = stitch_matching_edges(
      trial, matching_boundary_edges(trial, detail::BoundaryIndex(trial), tolerance, threads),
      tolerance);
  std::vector<char> left_over(junctions.size(), 0);
  bool any_left_over = false;
  for (const auto v : trial.vertices()) {
    const int junction = trial.property(junction_of, v);
    if (junction > 0) left_over[junction - 1] = 1, any_left_over = true;
  }
  if (any_left_over) {
    std::size_t j = 0;
    std::erase_if(junctions, [&](const detail::TJunction&) { return left_over[j++] != 0; });
    return std::nullopt;
  }
  trial.remove_property(junction_of);
  mesh = std::move(trial);
  report.t_junctions = junctions.size();
  report.vertices_merged -= junctions.size();  // the new vertices were never the file's
  return report;
}

}  // namespace

StitchReport stitch_borders(Mesh& mesh, const StitchOptions& options) {
  const double tolerance = options.tolerance >= 0.0 ? options.tolerance : default_tolerance(mesh);
  const detail::BoundaryIndex index(mesh);
  const unsigned threads = options.threads ? options.threads : detail::available_cores();
  const Matches matches = matching_boundary_edges(mesh, index, tolerance, threads);
  // An edge that already has a partner end to end is stitched to it, not split.
  std::vector<detail::TJunction> junctions =
      detail::find_t_junctions(mesh, index, tolerance, matches.on_another, threads);
  // A junction whose new vertex could not be merged (its stitch would not be clean) is dropped
  // and the rest tried again; each try drops at least one, and the tries are bounded because
  // each copies the mesh.
  constexpr int kMaxTries = 3;
  for (int attempt = 0; attempt < kMaxTries && !junctions.empty(); ++attempt) {
    if (auto report = stitch_with_junctions(mesh, tolerance, threads, junctions)) return *report;
  }
  return stitch_matching_edges(mesh, matches, tolerance);
}

}  // namespace holefill
