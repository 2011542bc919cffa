#include "holefill/weld.h"

#include <algorithm>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "available_cores.h"
#include "boundary_points.h"
#include "holefill/components.h"
#include "parallel_indices.h"
#include "vertex_link.h"
#include "vertex_merge.h"

namespace holefill {
namespace {

// At most this many boundary vertices are welded at one position: only the nearest few are looked
// at, so that the work is linear in the boundary whatever the tolerance (every point within 1e10
// of every other on a grid of face-by-face squares took 650 s for 60,000 faces).
constexpr std::size_t kMostAtOnePosition = 8;

// The piece (components.h) of a vertex, through any face around it; -1 for a vertex of no face.
int piece_of(const Mesh& mesh, const MeshPieces& pieces, VertexHandle v) {
  for (const auto f : mesh.vf_range(v)) return pieces.piece_of_face[f.idx()];
  return -1;
}

bool has_repeats(std::vector<int> values) {
  std::sort(values.begin(), values.end());
  return std::adjacent_find(values.begin(), values.end()) != values.end();
}

// Whether welding `group` (lowest index first) into its first vertex keeps every face a triangle
// and every edge used at most once each way: the group's link edges (vertex_link.h), neighbours
// renamed as they will be, never name the kept vertex, and no neighbour starts or ends two of them.
// Unlike a stitch's merge, the welded vertex may carry several fans: the pinch that the holes are
// then separated at.
bool weld_is_clean(const Mesh& mesh, const std::vector<VertexHandle>& group,
                   const std::vector<int>& kept_of) {
  std::vector<std::pair<int, int>> link;
  for (const auto v : group) {
    detail::add_link_edges(
        mesh, v, [&](int u) { return kept_of[u]; }, link);
  }
  const int kept = group.front().idx();
  std::vector<int> starts, ends;
  for (const auto& [a, b] : link) {
    if (a == kept || b == kept || a == b) return false;
    starts.push_back(a);
    ends.push_back(b);
  }
  return !has_repeats(std::move(starts)) && !has_repeats(std::move(ends));
}

// Groups of boundary vertices within the tolerance of each other, on one piece, no two joined by
// an edge; each group lowest index first, groups in the order of their lowest vertex.
std::vector<std::vector<VertexHandle>> touching_groups(const Mesh& mesh, double tolerance,
                                                       unsigned threads) {
  const detail::BoundaryIndex index(mesh);
  const detail::BoundaryPoints& points = index.points;
  if (points.vertices.size() < 2) return {};
  // The pairs within the tolerance, found in blocks of points on `threads` threads (0: every
  // core) and taken in the points' order, so that the groups are those of one thread.
  constexpr std::size_t kBlock = std::size_t{1} << 13;
  const std::size_t n = points.vertices.size();
  std::vector<std::vector<std::pair<VertexHandle, VertexHandle>>> block_pairs((n + kBlock - 1) /
                                                                              kBlock);
  detail::for_each_index(
      block_pairs.size(), threads ? threads : detail::available_cores(), [&](std::size_t block) {
        std::vector<std::size_t> within;
        for (std::size_t s = block * kBlock; s < std::min(n, (block + 1) * kBlock); ++s) {
          const VertexHandle a = points.vertices[s];
          // Crowded: more than a few points within the tolerance (a tolerance far above the edge
          // length) is no place where holes touch; it is left apart.
          if (!detail::points_within_tolerance(index, mesh.point(a), tolerance, kMostAtOnePosition,
                                               within)) {
            continue;
          }
          for (const std::size_t k : within) {
            const VertexHandle b = points.vertices[k];
            if (b.idx() <= a.idx() || mesh.find_halfedge(a, b).is_valid()) continue;
            block_pairs[block].emplace_back(a, b);
          }
        }
      });
  // The pieces only for the pairs that need them: most meshes have none, and finding the pieces
  // of a 1.4M-face mesh was a tenth of filling it.
  std::optional<MeshPieces> pieces;
  detail::VertexGroups groups(mesh.n_vertices());
  bool any = false;
  for (const auto& pairs : block_pairs) {
    for (const auto& [a, b] : pairs) {
      if (!pieces) pieces = mesh_pieces(mesh);
      if (piece_of(mesh, *pieces, a) != piece_of(mesh, *pieces, b)) continue;
      groups.join(a.idx(), b.idx());
      any = true;
    }
  }
  if (!any) return {};
  std::map<int, std::vector<VertexHandle>> by_root;
  for (const auto v : points.vertices) by_root[groups.root(v.idx())].push_back(v);
  std::vector<std::vector<VertexHandle>> result;
  for (auto& [root, group] : by_root) {
    if (group.size() < 2) continue;
    std::sort(group.begin(), group.end());
    result.push_back(std::move(group));
  }
  return result;
}

// The fans of faces around `v` (faces joined across the edges at v that have a face on both
// sides), each in increasing face index, ordered by their lowest face.
std::vector<std::vector<FaceHandle>> fans_around(const Mesh& mesh, VertexHandle v) {
  std::vector<FaceHandle> faces;
  for (const auto f : mesh.vf_range(v)) faces.push_back(f);
  std::sort(faces.begin(), faces.end());
  const auto position = [&](FaceHandle f) {
    return static_cast<int>(std::lower_bound(faces.begin(), faces.end(), f) - faces.begin());
  };
  detail::VertexGroups joined(faces.size());
  for (const auto h : mesh.voh_range(v)) {
    const FaceHandle left = mesh.face_handle(h), right = mesh.opposite_face_handle(h);
    if (left.is_valid() && right.is_valid()) joined.join(position(left), position(right));
  }
  std::map<int, std::vector<FaceHandle>> by_root;  // the root is the fan's lowest face
  for (std::size_t i = 0; i < faces.size(); ++i) {
    by_root[joined.root(static_cast<int>(i))].push_back(faces[i]);
  }
  std::vector<std::vector<FaceHandle>> fans;
  for (auto& [root, fan] : by_root) fans.push_back(std::move(fan));
  return fans;
}

}  // namespace

std::size_t unweld_open_pinches(Mesh& mesh, const std::vector<Point>& welded_at) {
  if (welded_at.empty()) return 0;
  std::vector<VertexHandle> pinches;
  for (const auto v : mesh.vertices()) {
    if (!mesh.is_manifold(v) &&
        std::find(welded_at.begin(), welded_at.end(), mesh.point(v)) != welded_at.end()) {
      pinches.push_back(v);
    }
  }
  if (pinches.empty()) return 0;
  const Mesh before = mesh;
  // (face, pinch vertex) -> the vertex that corner moves to
  std::map<std::pair<int, int>, VertexHandle> moved;
  std::vector<FaceHandle> faces;
  std::size_t added = 0;
  for (const auto v : pinches) {
    const auto fans = fans_around(mesh, v);
    for (std::size_t i = 1; i < fans.size(); ++i) {
      const VertexHandle copy = mesh.add_vertex(mesh.point(v));
      mesh.copy_all_properties(v, copy, true);
      ++added;
      for (const auto f : fans[i]) {
        moved[{f.idx(), v.idx()}] = copy;
        faces.push_back(f);
      }
    }
  }
  const bool moved_all = detail::move_corners(mesh, faces, [&](FaceHandle f, VertexHandle v) {
    const auto found = moved.find({f.idx(), v.idx()});
    return found == moved.end() ? v : found->second;
  });
  if (moved_all) return added;
  mesh = before;  // OpenMesh refused a face (move_corners left the copies added above)
  return 0;
}

bool has_touching_vertices(const Mesh& mesh, double tolerance, unsigned threads) {
  return !touching_groups(mesh, tolerance, threads).empty();
}

WeldReport weld_touching_vertices(Mesh& mesh, double tolerance, const std::vector<Point>& apart,
                                  unsigned threads) {
  WeldReport report;
  auto groups = touching_groups(mesh, tolerance, threads);
  std::erase_if(groups, [&](const std::vector<VertexHandle>& group) {
    return std::any_of(group.begin(), group.end(), [&](VertexHandle v) {
      return std::find(apart.begin(), apart.end(), mesh.point(v)) != apart.end();
    });
  });
  if (groups.empty()) return report;
  std::vector<int> kept_of(mesh.n_vertices());
  for (const auto v : mesh.vertices()) kept_of[v.idx()] = v.idx();
  for (const auto& group : groups) {
    for (const auto v : group) kept_of[v.idx()] = group.front().idx();
  }
  // A group whose weld is not clean stays apart; the others' checks see it as it stays.
  for (const auto& group : groups) {
    if (weld_is_clean(mesh, group, kept_of)) continue;
    for (const auto v : group) kept_of[v.idx()] = v.idx();
    ++report.positions_left;
  }
  for (const auto& group : groups) {
    if (kept_of[group.back().idx()] == group.back().idx()) continue;
    ++report.positions;
    report.welded_at.push_back(mesh.point(group.front()));
    report.vertices_welded += group.size() - 1;
  }
  if (report.positions == 0) return report;
  if (!detail::merge_vertices(mesh, kept_of)) {  // OpenMesh refused a face: nothing welded
    report.positions_left += report.positions;
    report.positions = report.vertices_welded = 0;
    report.welded_at.clear();
  }
  return report;
}

}  // namespace holefill
