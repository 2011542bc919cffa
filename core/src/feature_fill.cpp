#include "feature_fill.h"

#include <algorithm>
#include <chrono>
#include <numeric>
#include <unordered_map>

#include "patch_intersections.h"
#include "stage_undo.h"

namespace holefill::detail {
namespace {

// Splits the loop of `loops` that holds nodes u and w along a path between them (`interior`:
// its nodes after u, before w) into the loop from u to w with the path back, and the loop from
// w to u with the path on to w. False when no loop holds both (paths that cross), or a part
// would have fewer than three nodes.
bool split_loop(std::vector<std::vector<int>>& loops, int u, int w,
                const std::vector<int>& interior) {
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const std::vector<int> loop = loops[l];
    const auto iu = std::find(loop.begin(), loop.end(), u);
    const auto iw = std::find(loop.begin(), loop.end(), w);
    if (iu == loop.end() || iw == loop.end()) continue;
    const std::size_t m = loop.size(), i = iu - loop.begin(), j = iw - loop.begin();
    std::vector<int> first, second;
    for (std::size_t k = i;; k = (k + 1) % m) {
      first.push_back(loop[k]);
      if (k == j) break;
    }
    first.insert(first.end(), interior.rbegin(), interior.rend());
    for (std::size_t k = j;; k = (k + 1) % m) {
      second.push_back(loop[k]);
      if (k == i) break;
    }
    second.insert(second.end(), interior.begin(), interior.end());
    if (first.size() < 3 || second.size() < 3) return false;
    loops[l] = std::move(first);
    loops.push_back(std::move(second));
    return true;
  }
  return false;
}

bool mesh_adjacent(const Mesh& mesh, VertexHandle a, VertexHandle b) {
  for (const auto v : mesh.vv_range(a)) {
    if (v == b) return true;
  }
  return false;
}

// A sub-loop's polygon for the dynamic program: the mesh faces across the hole's own edges, no
// face across a path's edges, and the chords that exist already as mesh edges forbidden.
HolePolygon polygon_of(const Mesh& mesh, const Hole& hole, const FeatureLoops& split,
                       const std::vector<int>& loop) {
  const int n = static_cast<int>(hole.size()), m = static_cast<int>(loop.size());
  HolePolygon polygon;
  std::unordered_map<int, int> position_of_vertex;
  for (int i = 0; i < m; ++i) {
    const int x = loop[i], y = loop[(i + 1) % m];
    polygon.points.push_back(x < n ? mesh.point(hole.vertices[x]) : split.new_points[x - n]);
    const bool hole_edge = x < n && y < n && y == (x + 1) % n;
    polygon.outside_normals.push_back(
        hole_edge ? mesh.calc_face_normal(mesh.opposite_face_handle(hole.halfedges[x]))
                  : Point(0.0, 0.0, 0.0));
    if (x < n) position_of_vertex[hole.vertices[x].idx()] = i;
  }
  // A chord between two points of one continued path would leave both regions' surfaces (on a
  // curved crease it cuts across the other face's side).
  for (const auto& chain : split.chains) {
    std::vector<int> on_chain;
    for (int i = 0; i < m; ++i) {
      if (std::find(chain.begin(), chain.end(), loop[i]) != chain.end()) on_chain.push_back(i);
    }
    for (std::size_t a = 0; a < on_chain.size(); ++a) {
      for (std::size_t b = a + 1; b < on_chain.size(); ++b) {
        const int i = on_chain[a], k = on_chain[b];
        if (k - i != 1 && k - i != m - 1) polygon.forbidden_chords.emplace_back(i, k);
      }
    }
  }
  for (const auto& [vertex, i] : position_of_vertex) {
    for (const auto neighbour : mesh.vv_range(VertexHandle(vertex))) {
      const auto found = position_of_vertex.find(neighbour.idx());
      if (found == position_of_vertex.end()) continue;
      const int k = found->second;
      if (i < k && k - i != 1 && k - i != m - 1) polygon.forbidden_chords.emplace_back(i, k);
    }
  }
  std::sort(polygon.forbidden_chords.begin(), polygon.forbidden_chords.end());
  return polygon;
}

struct FeaturePlan {
  FeatureLoops split;
  std::vector<PolygonTriangulation> triangulations;  // one per sub-loop
  std::string failure;
};

FeaturePlan plan_feature_fill(const Mesh& mesh, const Hole& hole, const HoleFeatures& features,
                              const TriangulateOptions& options) {
  FeaturePlan plan;
  plan.split = split_along_features(mesh, hole, features);
  if (!plan.split.failure.empty()) {
    plan.failure = plan.split.failure;
    return plan;
  }
  for (const auto& loop : plan.split.loops) {
    auto triangulation = triangulate_polygon(polygon_of(mesh, hole, plan.split, loop), options);
    if (!triangulation || triangulation->quality.degenerate > 0) {
      plan.failure =
          "a region between the continued features has no triangulation without a "
          "degenerate triangle or a duplicated edge";
      return plan;
    }
    plan.triangulations.push_back(std::move(*triangulation));
  }
  return plan;
}

// Adds the planned patch: the paths' new vertices, then each sub-loop's triangles. The patch
// is empty, the mesh unchanged, when the mesh refuses a triangle.
Patch add_feature_patch(Mesh& mesh, const Hole& hole, const FeaturePlan& plan,
                        std::vector<VertexHandle>& node_vertices) {
  const StageUndo nothing(mesh, Patch{});
  PatchTags tags(mesh);
  Patch patch;
  patch.hole_id = hole.id;
  patch.stage = Stage::Triangulated;
  patch.boundary = hole.vertices;
  node_vertices = hole.vertices;
  for (const Point& p : plan.split.new_points) {
    const VertexHandle v = mesh.add_vertex(p);
    mesh.property(tags.vertex_stage, v) = static_cast<std::uint8_t>(Stage::Triangulated);
    node_vertices.push_back(v);
    patch.new_vertices.push_back(v);
  }
  for (std::size_t l = 0; l < plan.split.loops.size(); ++l) {
    const auto& loop = plan.split.loops[l];
    for (const auto& t : plan.triangulations[l].triangles) {
      const FaceHandle face = mesh.add_face(node_vertices[loop[t[0]]], node_vertices[loop[t[1]]],
                                            node_vertices[loop[t[2]]]);
      if (!face.is_valid()) {
        nothing.undo(mesh, patch);
        return Patch{};
      }
      mesh.property(tags.face_stage, face) = static_cast<std::uint8_t>(Stage::Triangulated);
      patch.faces.push_back(face);
    }
  }
  return patch;
}

}  // namespace

FeatureLoops split_along_features(const Mesh& mesh, const Hole& hole,
                                  const HoleFeatures& features) {
  FeatureLoops split;
  const int n = static_cast<int>(hole.size());
  split.loops.emplace_back(n);
  std::iota(split.loops[0].begin(), split.loops[0].end(), 0);
  auto add_path = [&](const std::vector<Point>& path) {
    std::vector<int> nodes;
    for (const Point& p : path) {
      nodes.push_back(n + static_cast<int>(split.new_points.size()));
      split.new_points.push_back(p);
    }
    return nodes;
  };
  auto chain = [](int from, std::vector<int> nodes, int to) {
    nodes.insert(nodes.begin(), from);
    nodes.push_back(to);
    return nodes;
  };
  bool ok = true;
  for (const auto& junction : features.junctions) {
    std::vector<int> entries;
    for (const int l : junction.lines) entries.push_back(features.lines[l].entry);
    if (!junction.corner) {
      const auto path = add_path(junction.paths[0]);
      split.chains.push_back(chain(entries[0], path, entries[1]));
      ok = ok && (!path.empty() ||
                  !mesh_adjacent(mesh, hole.vertices[entries[0]], hole.vertices[entries[1]]));
      ok = ok && split_loop(split.loops, entries[0], entries[1], path);
      continue;
    }
    std::vector<std::vector<int>> paths;
    for (const auto& path : junction.paths) paths.push_back(add_path(path));
    const int corner = n + static_cast<int>(split.new_points.size());
    split.new_points.push_back(junction.corner_point);
    for (std::size_t k = 0; k < paths.size(); ++k) {
      split.chains.push_back(chain(entries[k], paths[k], corner));
    }
    std::vector<int> through = paths[0];
    through.push_back(corner);
    through.insert(through.end(), paths[1].rbegin(), paths[1].rend());
    ok = ok && split_loop(split.loops, entries[0], entries[1], through);
    for (std::size_t k = 2; k < paths.size(); ++k) {
      ok = ok && split_loop(split.loops, entries[k], corner, paths[k]);
    }
  }
  if (!ok) {
    split.failure =
        "the continued features do not split the hole into regions (they cross, or "
        "one runs along the hole's boundary)";
  }
  return split;
}

bool feature_triangulate_stage(Mesh& mesh, const Hole& hole, HoleFill& fill,
                               const FillOptions& options, const MeshFaceIndex* index) {
  const auto start = std::chrono::steady_clock::now();
  fill.features = find_hole_features(mesh, hole, options.features);
  fill.creases.clear();
  FeaturePlan plan;
  plan.failure = fill.features.note;
  if (fill.features.continued()) {
    plan = plan_feature_fill(mesh, hole, fill.features, options.triangulate);
  }
  std::vector<VertexHandle> node_vertices;
  Patch patch;
  if (fill.features.continued() && plan.failure.empty()) {
    patch = add_feature_patch(mesh, hole, plan, node_vertices);
    if (patch.faces.empty()) plan.failure = "the mesh around the hole refused a patch triangle";
  }
  if (!patch.faces.empty()) {
    if (has_degenerate_face(mesh, patch)) {
      plan.failure = "the patch along them had a degenerate triangle";
    } else if (const auto pairs =
                   patch_intersections(mesh, patch, index, !options.allow_intersections).size()) {
      plan.failure = "the patch along them cut the mesh (" + std::to_string(pairs) +
                     " intersecting pairs of triangles)";
    }
    if (!plan.failure.empty()) StageUndo(mesh, Patch{}).undo(mesh, patch);
  }
  fill.times.triangulate_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!plan.failure.empty()) {
    fill.features_note = "features not continued: " + plan.failure;
    return false;
  }
  if (patch.faces.empty()) return false;
  fill.patch = std::move(patch);
  for (const auto& chain : plan.split.chains) {
    auto& vertices = fill.creases.emplace_back();
    for (const int node : chain) vertices.push_back(node_vertices[node]);
  }
  return true;
}

}  // namespace holefill::detail
