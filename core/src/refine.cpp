#include "holefill/refine.h"

#include <algorithm>
#include <cmath>

#include "geometry.h"
#include "patch_face_set.h"

namespace holefill {
namespace {

// Whether the angles at c and d opposite edge a-b clearly sum to at most pi, without atan2: for
// angles in (0, pi), alpha + beta <= pi exactly when cot(alpha) + cot(beta) >= 0. The margin
// leaves every case that rounding could decide either way to the exact test.
bool clearly_delaunay(const Point& a, const Point& b, const Point& c, const Point& d) {
  const Point ca = a - c, cb = b - c, da = a - d, db = b - d;
  const double sin_c = OpenMesh::cross(ca, cb).norm(), sin_d = OpenMesh::cross(da, db).norm();
  if (!(sin_c > 0.0 && sin_d > 0.0)) return false;
  const double cot_c = OpenMesh::dot(ca, cb) / sin_c, cot_d = OpenMesh::dot(da, db) / sin_d;
  return cot_c + cot_d > 1e-6 * (std::abs(cot_c) + std::abs(cot_d) + 1.0);
}

// An edge the refinement may swap: both its faces belong to this patch (so it is neither on the
// hole's boundary nor in the original mesh), and the swapped edge does not exist yet.
bool swappable(const Mesh& mesh, const detail::PatchFaceSet& patch_faces, EdgeHandle e) {
  const auto h0 = mesh.halfedge_handle(e, 0), h1 = mesh.halfedge_handle(e, 1);
  if (!patch_faces.contains(mesh.face_handle(h0)) || !patch_faces.contains(mesh.face_handle(h1))) {
    return false;
  }
  return should_swap_edge(mesh, e) && mesh.is_flip_ok(e);  // the geometric test is cheaper
}

// Bound on relaxation sweeps: non-planar Delaunay flipping terminates in practice, but a
// pathological patch must not loop forever.
constexpr int kMaxRelaxSweeps = 100;
constexpr int kMaxRefineRounds = 200;

std::size_t relax_edges(Mesh& mesh, const detail::PatchFaceSet& patch_faces,
                        const std::vector<FaceHandle>& faces) {
  std::size_t swaps = 0;
  for (int sweep = 0; sweep < kMaxRelaxSweeps; ++sweep) {
    std::size_t swapped_now = 0;
    for (const auto f : faces) {
      // Copy the edges first: a swap relinks the face, which would derail a circulator.
      EdgeHandle edges[3];
      int count = 0;
      for (const auto e : mesh.fe_range(f)) edges[count++] = e;
      for (const auto e : edges) {
        if (swappable(mesh, patch_faces, e)) {
          mesh.flip(e);
          ++swapped_now;
        }
      }
    }
    swaps += swapped_now;
    if (swapped_now == 0) break;
  }
  return swaps;
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
  return relax_edges(mesh, detail::PatchFaceSet(patch), patch.faces);
}

RefineResult refine_patch(Mesh& mesh, Patch& patch, const RefineOptions& options) {
  RefineResult result;
  PatchTags tags(mesh);
  assign_boundary_scales(mesh, patch);
  detail::PatchFaceSet patch_faces(patch);
  const double tau = options.tau;
  result.vertex_cap = vertex_cap(mesh, patch, options.max_density);

  for (int round = 0; round < kMaxRefineRounds; ++round) {
    std::size_t splits_now = 0;
    const std::vector<FaceHandle> faces = patch.faces;
    for (const auto f : faces) {
      if (patch.faces.size() + 2 > options.max_patch_faces) {
        result.stopped_at_face_limit = true;
        break;
      }
      if (result.vertex_cap && patch.new_vertices.size() >= result.vertex_cap) {
        result.stopped_at_vertex_cap = true;
        break;
      }
      VertexHandle corner[3];
      int c = 0;
      for (const auto v : mesh.fv_range(f)) corner[c++] = v;
      const Point centroid =
          (mesh.point(corner[0]) + mesh.point(corner[1]) + mesh.point(corner[2])) / 3.0;
      const double centroid_scale =
          (mesh.property(tags.scale, corner[0]) + mesh.property(tags.scale, corner[1]) +
           mesh.property(tags.scale, corner[2])) /
          3.0;
      bool split = true;
      for (const auto v : corner) {
        const double reach = tau * (centroid - mesh.point(v)).norm();
        if (!(reach > centroid_scale && reach > mesh.property(tags.scale, v))) split = false;
      }
      if (!split) continue;

      std::vector<EdgeHandle> old_edges;
      for (const auto e : mesh.fe_range(f)) old_edges.push_back(e);
      const VertexHandle center = mesh.add_vertex(centroid);
      mesh.split(f, center);
      mesh.property(tags.scale, center) = centroid_scale;
      mesh.property(tags.vertex_stage, center) = static_cast<std::uint8_t>(Stage::Refined);
      patch.new_vertices.push_back(center);
      for (const auto nf : mesh.vf_range(center)) {
        if (patch_faces.insert(nf)) patch.faces.push_back(nf);
        mesh.property(tags.face_stage, nf) = static_cast<std::uint8_t>(Stage::Refined);
      }
      for (const auto e : old_edges) {
        if (swappable(mesh, patch_faces, e)) {
          mesh.flip(e);
          ++result.swaps;
        }
      }
      ++splits_now;
    }
    result.splits += splits_now;
    if (splits_now == 0 || result.stopped_at_face_limit) break;
    result.swaps += relax_edges(mesh, patch_faces, patch.faces);
    if (result.stopped_at_vertex_cap) break;
  }
  if (options.remesh) result.remeshing = remesh_patch(mesh, patch, options.remeshing);
  return result;
}

bool should_swap_edge(const Mesh& mesh, EdgeHandle edge) {
  const auto h0 = mesh.halfedge_handle(edge, 0), h1 = mesh.halfedge_handle(edge, 1);
  if (mesh.is_boundary(h0) || mesh.is_boundary(h1)) return false;
  const Point& a = mesh.point(mesh.from_vertex_handle(h0));
  const Point& b = mesh.point(mesh.to_vertex_handle(h0));
  const Point& c = mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h0)));
  const Point& d = mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h1)));
  if (clearly_delaunay(a, b, c, d)) return false;  // most edges: no atan2 needed
  const double opposite_now = geometry::angle_at(c, a, b) + geometry::angle_at(d, a, b);
  const double opposite_swapped = geometry::angle_at(a, c, d) + geometry::angle_at(b, c, d);
  // On a curved patch both diagonals of a quad can see more than pi; swapping only when it lowers
  // the opposite-angle sum keeps relaxation from swapping an edge back and forth. The margin
  // keeps co-circular configurations still.
  constexpr double kMargin = 1e-9;
  return opposite_now > M_PI + kMargin && opposite_swapped < opposite_now - kMargin;
}

}  // namespace holefill
