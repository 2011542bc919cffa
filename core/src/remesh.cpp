#include "holefill/remesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <unordered_map>
#include <vector>

#include "geometry.h"
#include "holefill/triangulate.h"
#include "patch_face_set.h"

namespace holefill {
namespace {

constexpr int kRegularValence = 6;

using FaceSet = detail::PatchFaceSet;

bool in_patch(const FaceSet& patch_faces, FaceHandle f) { return patch_faces.contains(f); }

// target_valence(), with the patch's faces as a set.
int target_valence_in(const Mesh& mesh, const FaceSet& patch_faces, VertexHandle v) {
  double patch_angle = 0.0, other_angle = 0.0;
  int patch_triangles = 0, interior_patch_edges = 0;
  for (const auto h : mesh.voh_range(v)) {
    const FaceHandle f = mesh.face_handle(h);
    if (f.is_valid()) {
      const Point& b = mesh.point(mesh.to_vertex_handle(h));
      const Point& c = mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h)));
      const double angle = geometry::angle_at(mesh.point(v), b, c);
      (in_patch(patch_faces, f) ? patch_angle : other_angle) += angle;
      patch_triangles += in_patch(patch_faces, f);
    }
    interior_patch_edges +=
        in_patch(patch_faces, f) && in_patch(patch_faces, mesh.opposite_face_handle(h));
  }
  const int valence = static_cast<int>(mesh.valence(v));
  if (patch_triangles == valence) return kRegularValence;  // a new vertex, inside the patch
  // A boundary vertex: the edges outside the patch stay; the patch side should hold triangles of
  // about 60 degrees, i.e. its share of the vertex's six.
  const double share = patch_angle / std::max(patch_angle + other_angle, 1e-300);
  const int wanted_triangles = std::max(1, static_cast<int>(std::lround(kRegularValence * share)));
  return valence - interior_patch_edges + (wanted_triangles - 1);
}

// The corners of a flip: edge a-b between triangles (a, b, c) and (b, a, d) becomes c-d.
struct FlipQuad {
  VertexHandle a, b, c, d;
};

FlipQuad quad_of(const Mesh& mesh, EdgeHandle e) {
  const auto h0 = mesh.halfedge_handle(e, 0), h1 = mesh.halfedge_handle(e, 1);
  return {mesh.from_vertex_handle(h0), mesh.to_vertex_handle(h0),
          mesh.to_vertex_handle(mesh.next_halfedge_handle(h0)),
          mesh.to_vertex_handle(mesh.next_halfedge_handle(h1))};
}

// A flip (or a move) may make the smallest angle of the triangles it changes worse, for the
// valence's sake, but not below this (unless it was already): fairing a patch with slivers in it
// can squeeze them further.
constexpr double kSliverAngle = 20.0 * std::numbers::pi / 180.0;

// The flip keeps the surface's shape: both new triangles are proper, face the way the old pair
// did, bend against each other no more than allowed, and are no slivers.
bool flip_keeps_shape(const Mesh& mesh, const FlipQuad& q, double max_dihedral) {
  const Point &a = mesh.point(q.a), &b = mesh.point(q.b), &c = mesh.point(q.c),
              &d = mesh.point(q.d);
  // Old triangles (a, b, c), (b, a, d); new ones (c, d, b) and (d, c, a).
  if (geometry::measure_triangle(c, d, b, false).degenerate ||
      geometry::measure_triangle(d, c, a, false).degenerate) {
    return false;
  }
  const Point old1 = geometry::area_normal(a, b, c), old2 = geometry::area_normal(b, a, d);
  const Point new1 = geometry::area_normal(c, d, b), new2 = geometry::area_normal(d, c, a);
  const Point old_sum = old1.normalized() + old2.normalized();
  if (OpenMesh::dot(new1, old_sum) <= 0.0 || OpenMesh::dot(new2, old_sum) <= 0.0) return false;
  const double old_dihedral = geometry::angle_between_normals(old1.normalized(), old2.normalized());
  const double new_dihedral = geometry::angle_between_normals(new1.normalized(), new2.normalized());
  if (new_dihedral > std::max(max_dihedral, old_dihedral)) return false;
  const double old_min = std::min(geometry::min_angle(a, b, c), geometry::min_angle(b, a, d));
  const double new_min = std::min(geometry::min_angle(c, d, b), geometry::min_angle(d, c, a));
  return new_min >= std::min(old_min, kSliverAngle);
}

class PatchRemesher {
 public:
  PatchRemesher(Mesh& mesh, const Patch& patch, const RemeshOptions& options)
      : mesh_(mesh),
        patch_(patch),
        tags_(mesh),
        patch_faces_(patch),
        max_dihedral_(options.max_flip_dihedral_deg * std::numbers::pi / 180.0) {
    for (const auto v : patch.boundary) {
      target_[v.idx()] = target_valence_in(mesh, patch_faces_, v);
    }
    for (const auto v : patch.new_vertices) target_[v.idx()] = kRegularValence;
  }

  std::size_t flip_sweep() {
    std::size_t flips = 0;
    for (const auto e : interior_edges()) {
      if (!mesh_.is_flip_ok(e)) continue;
      const FlipQuad q = quad_of(mesh_, e);
      const int before =
          deviation(q.a, 0) + deviation(q.b, 0) + deviation(q.c, 0) + deviation(q.d, 0);
      const int after =
          deviation(q.a, -1) + deviation(q.b, -1) + deviation(q.c, +1) + deviation(q.d, +1);
      if (after >= before || !flip_keeps_shape(mesh_, q, max_dihedral_)) continue;
      mesh_.flip(e);
      for (int side = 0; side < 2; ++side) {
        mesh_.property(tags_.face_stage, mesh_.face_handle(mesh_.halfedge_handle(e, side))) =
            static_cast<std::uint8_t>(Stage::Refined);
      }
      ++flips;
    }
    return flips;
  }

  std::size_t relax_sweep() {
    std::size_t moves = 0;
    for (const auto v : patch_.new_vertices) {
      const auto target = tangential_centroid(v);
      if (!target) continue;
      const Point from = mesh_.point(v);
      const auto normals = fan_normals(v);
      const double smallest_angle = fan_min_angle(v);
      mesh_.set_point(v, *target);
      if (fan_stays_proper(v, normals) &&
          fan_min_angle(v) >= std::min(smallest_angle, kSliverAngle)) {
        ++moves;
      } else {
        mesh_.set_point(v, from);
      }
    }
    return moves;
  }

 private:
  // Interior patch edges (both faces in the patch), in a fixed order.
  std::vector<EdgeHandle> interior_edges() const {
    std::vector<EdgeHandle> edges;
    for (const auto f : patch_.faces) {
      for (const auto h : mesh_.fh_range(f)) {
        if (in_patch(patch_faces_, mesh_.opposite_face_handle(h)) &&
            mesh_.from_vertex_handle(h).idx() < mesh_.to_vertex_handle(h).idx()) {
          edges.push_back(mesh_.edge_handle(h));
        }
      }
    }
    return edges;
  }

  int deviation(VertexHandle v, int change) const {
    const int off = static_cast<int>(mesh_.valence(v)) + change - target_.at(v.idx());
    return off * off;
  }

  // The mean of v's neighbours, moved into v's tangent plane (the normal: the area-weighted
  // mean of its faces'); nothing when v's fan has no area.
  std::optional<Point> tangential_centroid(VertexHandle v) const {
    Point centroid(0.0, 0.0, 0.0), normal(0.0, 0.0, 0.0);
    int neighbours = 0;
    for (const auto u : mesh_.vv_range(v)) {
      centroid += mesh_.point(u);
      ++neighbours;
    }
    for (const auto f : mesh_.vf_range(v)) normal += area_normal(f);
    if (neighbours == 0 || !(normal.norm() > 0.0)) return std::nullopt;
    normal.normalize();
    const Point& p = mesh_.point(v);
    const Point step = centroid / neighbours - p;
    return p + (step - OpenMesh::dot(step, normal) * normal);
  }

  Point area_normal(FaceHandle f) const {
    std::array<Point, 3> p;
    int c = 0;
    for (const auto u : mesh_.fv_range(f)) p[c++ % 3] = mesh_.point(u);
    return geometry::area_normal(p[0], p[1], p[2]);
  }

  std::vector<Point> fan_normals(VertexHandle v) const {
    std::vector<Point> normals;
    for (const auto f : mesh_.vf_range(v)) normals.push_back(mesh_.calc_face_normal(f));
    return normals;
  }

  double fan_min_angle(VertexHandle v) const {
    double smallest = std::numbers::pi;
    for (const auto f : mesh_.vf_range(v)) {
      std::array<Point, 3> p;
      int c = 0;
      for (const auto u : mesh_.fv_range(f)) p[c++ % 3] = mesh_.point(u);
      smallest = std::min(smallest, geometry::min_angle(p[0], p[1], p[2]));
    }
    return smallest;
  }

  // No face around v became degenerate or turned over (normals `before`, in the same order).
  bool fan_stays_proper(VertexHandle v, const std::vector<Point>& before) const {
    std::size_t i = 0;
    for (const auto f : mesh_.vf_range(v)) {
      std::array<Point, 3> p;
      int c = 0;
      for (const auto u : mesh_.fv_range(f)) p[c++ % 3] = mesh_.point(u);
      if (geometry::measure_triangle(p[0], p[1], p[2], false).degenerate) return false;
      if (OpenMesh::dot(geometry::area_normal(p[0], p[1], p[2]), before[i++]) <= 0.0) return false;
    }
    return true;
  }

  Mesh& mesh_;
  const Patch& patch_;
  PatchTags tags_;
  FaceSet patch_faces_;
  std::unordered_map<int, int> target_;
  double max_dihedral_;
};

}  // namespace

int target_valence(const Mesh& mesh, const Patch& patch, VertexHandle vertex) {
  return target_valence_in(mesh, FaceSet(patch), vertex);
}

RemeshResult remesh_patch(Mesh& mesh, const Patch& patch, const RemeshOptions& options) {
  RemeshResult result;
  if (patch.new_vertices.empty()) return result;
  PatchRemesher remesher(mesh, patch, options);
  for (int round = 0; round < options.iterations; ++round) {
    result.flips += remesher.flip_sweep();
    result.moves += remesher.relax_sweep();
  }
  return result;
}

}  // namespace holefill
