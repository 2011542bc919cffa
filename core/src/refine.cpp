#include "holefill/refine.h"

#include <algorithm>
#include <cmath>

#include "delaunay_swap.h"
#include "flat_patch.h"
#include "patch_face_set.h"
#include "refine_scaled.h"

namespace holefill {
namespace {

// Bound on relaxation sweeps: non-planar Delaunay flipping terminates in practice, but a
// pathological patch must not loop forever.
constexpr int kMaxRelaxSweeps = 100;
constexpr int kMaxRefineRounds = 200;

// Splits the face at its centroid c when tau * |c - m| exceeds both sigma(c) and sigma(m) for
// every corner m, then swaps the face's old edges where the relaxation would; false when the face
// stays.
bool split_where_too_coarse(detail::FlatPatch& flat, int face, double tau, RefineResult& result) {
  const auto corner = flat.corners(face);
  const Point centroid =
      (flat.point(corner[0]) + flat.point(corner[1]) + flat.point(corner[2])) / 3.0;
  const double centroid_scale =
      (flat.scale(corner[0]) + flat.scale(corner[1]) + flat.scale(corner[2])) / 3.0;
  for (const int v : corner) {
    const double reach = tau * (centroid - flat.point(v)).norm();
    if (!(reach > centroid_scale && reach > flat.scale(v))) return false;
  }
  const auto old_edges = flat.edges(face);
  flat.split(face, centroid, centroid_scale);
  for (const int e : old_edges) {
    if (flat.swappable(e)) {
      flat.flip(e);
      ++result.swaps;
    }
  }
  return true;
}

// Which limit stops refinement before it tests another face: the face limit first.
enum class Stop { None, FaceLimit, VertexCap, Cancelled };

// A cancel is looked at once per this many faces tested (well under a millisecond of splits).
constexpr int kFacesBetweenCancelChecks = 4096;

Stop limit_reached(const detail::FlatPatch& flat, std::size_t vertices_before,
                   const RefineOptions& options, std::size_t vertex_cap) {
  if (static_cast<std::size_t>(flat.face_count()) + 2 > options.max_patch_faces) {
    return Stop::FaceLimit;
  }
  const std::size_t vertices = vertices_before + flat.new_vertex_count();
  return vertex_cap && vertices >= vertex_cap ? Stop::VertexCap : Stop::None;
}

// One round: every face that was there when it began, in order, split where too coarse, until a
// limit stops it. The limits hold before a face when they held before the round or after the
// last split (nothing else changes them), so they are asked then, while faces remain.
Stop refine_round(detail::FlatPatch& flat, std::size_t vertices_before,
                  const RefineOptions& options, RefineResult& result, std::size_t& splits,
                  const Progress* progress) {
  const int faces_now = flat.face_count();  // faces split off in this round wait for the next
  Stop stop =
      faces_now > 0 ? limit_reached(flat, vertices_before, options, result.vertex_cap) : Stop::None;
  for (int face = flat.next_untested(0, faces_now); stop == Stop::None && face < faces_now;
       face = flat.next_untested(face + 1, faces_now)) {
    if (face % kFacesBetweenCancelChecks == 0 && is_cancelled(progress)) return Stop::Cancelled;
    if (!split_where_too_coarse(flat, face, options.tau, result)) {
      flat.settle_face(face);
      continue;
    }
    ++splits;
    if (face + 1 < faces_now) {
      stop = limit_reached(flat, vertices_before, options, result.vertex_cap);
    }
  }
  return stop;
}

// RefineOptions::max_density's cap on the new vertices of this patch; 0 when there is none (no
// cap asked for, or no boundary scale to measure the density by). Needs the boundary scales.
std::size_t vertex_cap(Mesh& mesh, const Patch& patch, double max_density) {
  PatchTags tags(mesh);
  double area = 0.0, scale = 0.0;
  for (const auto f : patch.faces) area += mesh.calc_face_area(f);
  for (const auto v : patch.boundary) scale += mesh.property(tags.scale, v);
  scale /= static_cast<double>(std::max<std::size_t>(1, patch.boundary.size()));
  const double cap = max_density * area / (scale * scale);
  if (!(max_density > 0.0) || !(cap < 1e15)) return 0;
  return std::max<std::size_t>(static_cast<std::size_t>(std::ceil(cap)), patch.boundary.size());
}

}  // namespace

void assign_boundary_scales(Mesh& mesh, const Patch& patch) {
  PatchTags tags(mesh);
  const detail::PatchFaceSet patch_faces(patch);
  for (const auto v : patch.boundary) {
    double total = 0.0;
    int count = 0;
    for (const auto h : mesh.voh_range(v)) {
      const FaceHandle left = mesh.face_handle(h);
      const FaceHandle right = mesh.opposite_face_handle(h);
      const bool original = (left.is_valid() && !patch_faces.contains(left)) ||
                            (right.is_valid() && !patch_faces.contains(right));
      if (!original) continue;
      total += mesh.calc_edge_length(h);
      ++count;
    }
    mesh.property(tags.scale, v) = count ? total / count : 0.0;
  }
}

std::size_t relax_patch_edges(Mesh& mesh, const Patch& patch) {
  detail::FlatPatch flat(mesh, patch, OpenMesh::VPropHandleT<double>());
  const std::size_t swaps = flat.relax(kMaxRelaxSweeps);
  if (swaps) flat.write_links(mesh);
  return swaps;
}

RefineResult refine_patch(Mesh& mesh, Patch& patch, const RefineOptions& options,
                          const Progress* progress) {
  assign_boundary_scales(mesh, patch);
  return detail::refine_with_scales(mesh, patch, options, progress);
}

RefineResult detail::refine_with_scales(Mesh& mesh, Patch& patch, const RefineOptions& options,
                                        const Progress* progress) {
  RefineResult result;
  PatchTags tags(mesh);
  result.vertex_cap = vertex_cap(mesh, patch, options.max_density);
  // The splits and swaps run on the patch's own arrays; the mesh changes once, at the end.
  detail::FlatPatch flat(mesh, patch, tags.scale);
  const std::size_t vertices_before = patch.new_vertices.size();
  for (int round = 0; round < kMaxRefineRounds; ++round) {
    std::size_t splits_now = 0;
    const Stop stop = refine_round(flat, vertices_before, options, result, splits_now, progress);
    if (stop == Stop::Cancelled || is_cancelled(progress)) return result;
    result.stopped_at_face_limit = stop == Stop::FaceLimit;
    result.stopped_at_vertex_cap = stop == Stop::VertexCap;
    result.splits += splits_now;
    if (splits_now == 0 || result.stopped_at_face_limit) break;
    result.swaps += flat.relax(kMaxRelaxSweeps);
    if (result.stopped_at_vertex_cap) break;
  }
  flat.write_back(mesh, tags, patch);
  if (options.remesh && !is_cancelled(progress))
    result.remeshing = remesh_patch(mesh, patch, options.remeshing);
  return result;
}

bool should_swap_edge(const Mesh& mesh, EdgeHandle edge) {
  const auto h0 = mesh.halfedge_handle(edge, 0), h1 = mesh.halfedge_handle(edge, 1);
  if (mesh.is_boundary(h0) || mesh.is_boundary(h1)) return false;
  return detail::should_swap_quad(mesh.point(mesh.from_vertex_handle(h0)),
                                  mesh.point(mesh.to_vertex_handle(h0)),
                                  mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h0))),
                                  mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h1))));
}

}  // namespace holefill
