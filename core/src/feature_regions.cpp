#include "feature_regions.h"

#include <algorithm>
#include <memory>
#include <unordered_map>
#include <unordered_set>

#include "patch_face_set.h"
#include "refine_scaled.h"

namespace holefill::detail {
namespace {

std::uint64_t edge_key(VertexHandle a, VertexHandle b) {
  const auto lo = static_cast<std::uint32_t>(std::min(a.idx(), b.idx()));
  const auto hi = static_cast<std::uint32_t>(std::max(a.idx(), b.idx()));
  return (std::uint64_t{hi} << 32) | lo;
}

// The crease edges, by their end vertices.
std::unordered_set<std::uint64_t> crease_edges(
    const std::vector<std::vector<VertexHandle>>& creases) {
  std::unordered_set<std::uint64_t> edges;
  for (const auto& chain : creases) {
    for (std::size_t i = 1; i < chain.size(); ++i) edges.insert(edge_key(chain[i - 1], chain[i]));
  }
  return edges;
}

bool is_crease(const Mesh& mesh, HalfedgeHandle h, const std::unordered_set<std::uint64_t>& edges) {
  return edges.count(edge_key(mesh.from_vertex_handle(h), mesh.to_vertex_handle(h))) > 0;
}

// Sets each crease vertex the patch added (not an entry on the hole's boundary) the mean length
// of its crease edges as its scale: the density the crease was laid out at.
void assign_crease_scales(Mesh& mesh, const Patch& patch,
                          const std::vector<std::vector<VertexHandle>>& creases) {
  const std::unordered_set<int> added = [&] {
    std::unordered_set<int> ids;
    for (const auto v : patch.new_vertices) ids.insert(v.idx());
    return ids;
  }();
  std::unordered_map<int, std::pair<double, int>> lengths;
  for (const auto& chain : creases) {
    for (std::size_t i = 1; i < chain.size(); ++i) {
      const double length = (mesh.point(chain[i]) - mesh.point(chain[i - 1])).norm();
      for (const auto v : {chain[i - 1], chain[i]}) {
        if (!added.count(v.idx())) continue;
        lengths[v.idx()].first += length;
        ++lengths[v.idx()].second;
      }
    }
  }
  PatchTags tags(mesh);
  for (const auto& [v, sum] : lengths) {
    mesh.property(tags.scale, VertexHandle(v)) = sum.first / sum.second;
  }
}

}  // namespace

std::vector<Patch> crease_regions(const Mesh& mesh, const Patch& patch,
                                  const std::vector<std::vector<VertexHandle>>& creases) {
  const auto edges = crease_edges(creases);
  const PatchFaceSet in_patch(patch);
  std::unordered_map<int, int> region_of_face;
  std::vector<Patch> regions;
  for (const auto seed : patch.faces) {
    if (region_of_face.count(seed.idx())) continue;
    const int id = static_cast<int>(regions.size());
    Patch& region = regions.emplace_back();
    region.hole_id = patch.hole_id;
    region.stage = patch.stage;
    std::vector<FaceHandle> stack{seed};
    region_of_face[seed.idx()] = id;
    while (!stack.empty()) {
      const FaceHandle f = stack.back();
      stack.pop_back();
      for (const auto h : mesh.fh_range(f)) {
        const FaceHandle other = mesh.opposite_face_handle(h);
        if (!in_patch.contains(other) || is_crease(mesh, h, edges)) continue;
        if (region_of_face.emplace(other.idx(), id).second) stack.push_back(other);
      }
    }
  }
  for (const auto f : patch.faces) regions[region_of_face[f.idx()]].faces.push_back(f);
  std::unordered_set<int> on_crease, added;
  for (const auto& chain : creases) {
    for (const auto v : chain) on_crease.insert(v.idx());
  }
  for (const auto v : patch.new_vertices) added.insert(v.idx());
  for (auto& region : regions) {
    std::unordered_set<int> seen;
    for (const auto f : region.faces) {
      for (const auto v : mesh.fv_range(f)) {
        if (!seen.insert(v.idx()).second) continue;
        if (added.count(v.idx()) && !on_crease.count(v.idx())) continue;
        region.boundary.push_back(v);
      }
    }
    for (const auto v : patch.new_vertices) {
      if (seen.count(v.idx()) && !on_crease.count(v.idx())) region.new_vertices.push_back(v);
    }
  }
  return regions;
}

RefineResult refine_between_creases(Mesh& mesh, Patch& patch,
                                    const std::vector<std::vector<VertexHandle>>& creases,
                                    const RefineOptions& options, const Progress* progress) {
  enter_phase(progress, phase::kRefiningBetweenCreases);
  assign_boundary_scales(mesh, patch);
  assign_crease_scales(mesh, patch, creases);
  RefineResult total;
  for (Patch& region : crease_regions(mesh, patch, creases)) {
    if (is_cancelled(progress)) break;
    const std::size_t faces = region.faces.size(), vertices = region.new_vertices.size();
    const RefineResult result = refine_with_scales(mesh, region, options, progress);
    patch.faces.insert(patch.faces.end(), region.faces.begin() + faces, region.faces.end());
    patch.new_vertices.insert(patch.new_vertices.end(), region.new_vertices.begin() + vertices,
                              region.new_vertices.end());
    total.splits += result.splits;
    total.swaps += result.swaps;
    total.stopped_at_face_limit |= result.stopped_at_face_limit;
    total.stopped_at_vertex_cap |= result.stopped_at_vertex_cap;
    total.vertex_cap += result.vertex_cap;
    total.remeshing.flips += result.remeshing.flips;
    total.remeshing.moves += result.remeshing.moves;
  }
  return total;
}

std::function<bool(FaceHandle)> same_side_faces(
    const Mesh& mesh, const Patch& region, const std::vector<std::vector<VertexHandle>>& creases,
    double angle_degrees, int rings) {
  const auto edges = crease_edges(creases);
  // A vertex ring can take a fan's half to walk around: a few face steps per ring.
  const int depth = 6 * (rings + 1);
  auto reached = std::make_shared<std::unordered_set<int>>();
  std::vector<FaceHandle> frontier;
  for (const auto f : region.faces) {
    if (reached->insert(f.idx()).second) frontier.push_back(f);
  }
  for (int step = 0; step < depth && !frontier.empty(); ++step) {
    std::vector<FaceHandle> next;
    for (const auto f : frontier) {
      for (const auto h : mesh.fh_range(f)) {
        const FaceHandle other = mesh.opposite_face_handle(h);
        if (!other.is_valid() || reached->count(other.idx())) continue;
        if (is_crease(mesh, h, edges) || is_sharp_edge(mesh, mesh.edge_handle(h), angle_degrees)) {
          continue;
        }
        reached->insert(other.idx());
        next.push_back(other);
      }
    }
    frontier = std::move(next);
  }
  return [reached](FaceHandle f) { return f.is_valid() && reached->count(f.idx()) > 0; };
}

}  // namespace holefill::detail
