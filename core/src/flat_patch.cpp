#include "flat_patch.h"

#include <cmath>
#include <stdexcept>

#include "geometry.h"

namespace holefill::detail {
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

// The key of an unordered vertex pair (never FlatIndexMap's empty key: indices are below 2^31).
std::uint64_t pair_key(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b));
  const auto hi = static_cast<std::uint64_t>(std::max(a, b));
  return lo << 32 | hi;
}

}  // namespace

bool should_swap_quad(const Point& a, const Point& b, const Point& c, const Point& d) {
  if (clearly_delaunay(a, b, c, d)) return false;  // most edges: no atan2 needed
  const double opposite_now = geometry::angle_at(c, a, b) + geometry::angle_at(d, a, b);
  const double opposite_swapped = geometry::angle_at(a, c, d) + geometry::angle_at(b, c, d);
  // On a curved patch both diagonals of a quad can see more than pi; swapping only when it lowers
  // the opposite-angle sum keeps relaxation from swapping an edge back and forth. The margin
  // keeps co-circular configurations still.
  constexpr double kMargin = 1e-9;
  return opposite_now > M_PI + kMargin && opposite_swapped < opposite_now - kMargin;
}

FlatPatch::FlatPatch(const Mesh& mesh, const Patch& patch, OpenMesh::VPropHandleT<double> scale)
    : mesh_(mesh),
      mesh_vertices_(static_cast<int>(mesh.n_vertices())),
      mesh_edges_(static_cast<int>(mesh.n_edges())),
      mesh_faces_(static_cast<int>(mesh.n_faces())),
      edge_index_(2 * patch.faces.size()),
      vertex_index_(patch.faces.size()),
      edges_between_(8 * patch.faces.size()) {
  for (const auto f : patch.faces) {
    const int face = face_count();
    const HalfedgeHandle first = mesh.halfedge_handle(f);
    const HalfedgeHandle second = mesh.next_halfedge_handle(first);
    const HalfedgeHandle third = mesh.next_halfedge_handle(second);
    const int h0 = local_halfedge(mesh, first, scale), h1 = local_halfedge(mesh, second, scale),
              h2 = local_halfedge(mesh, third, scale);
    if (face_[h0] >= 0 || face_[h1] >= 0 || face_[h2] >= 0) {
      throw std::logic_error("refinement: the patch lists a face twice");
    }
    face_halfedge_.push_back(h0);
    face_handle_.push_back(f.idx());
    refined_.push_back(0);
    link(h0, h1, h2, face);
  }
  loaded_vertices_ = static_cast<int>(points_.size());
  loaded_edges_ = static_cast<int>(edge_handle_.size());
  loaded_faces_ = face_count();
  for (int e = 0; e < loaded_edges_; ++e) count_edge(to_[2 * e], to_[2 * e + 1], +1);
}

int FlatPatch::add_vertex(const Mesh& mesh, VertexHandle vertex,
                          OpenMesh::VPropHandleT<double> scale) {
  int& local = vertex_index_.find_or_insert(static_cast<std::uint64_t>(vertex.idx()), -1);
  if (local >= 0) return local;
  local = static_cast<int>(points_.size());
  points_.push_back(mesh.point(vertex));
  scales_.push_back(scale.is_valid() ? mesh.property(scale, vertex) : 0.0);
  vertex_handle_.push_back(vertex.idx());
  vertex_halfedge_.push_back(mesh.halfedge_handle(vertex).idx());
  return local;
}

int FlatPatch::local_halfedge(const Mesh& mesh, HalfedgeHandle halfedge,
                              OpenMesh::VPropHandleT<double> scale) {
  const int edge_index = halfedge.idx() / 2, side = halfedge.idx() % 2;
  const int known = edge_index_.find(static_cast<std::uint64_t>(edge_index), -1);
  if (known >= 0) return 2 * known + side;
  const HalfedgeHandle first = mesh.halfedge_handle(mesh.edge_handle(halfedge), 0);
  const int from = add_vertex(mesh, mesh.from_vertex_handle(first), scale);
  const int to = add_vertex(mesh, mesh.to_vertex_handle(first), scale);
  const int edge = add_edge(from, to);
  edge_handle_.push_back(edge_index);
  edge_index_.find_or_insert(static_cast<std::uint64_t>(edge_index), edge);
  return 2 * edge + side;
}

int FlatPatch::add_edge(int from, int to) {
  const int edge = static_cast<int>(to_.size() / 2);
  to_.insert(to_.end(), {to, from});
  next_.insert(next_.end(), {-1, -1});
  face_.insert(face_.end(), {-1, -1});
  return edge;
}

void FlatPatch::link(int h0, int h1, int h2, int face) {
  next_[h0] = h1;
  next_[h1] = h2;
  next_[h2] = h0;
  face_[h0] = face_[h1] = face_[h2] = face;
}

int FlatPatch::global_vertex(int vertex) const {
  return vertex < loaded_vertices_ ? vertex_handle_[vertex]
                                   : mesh_vertices_ + (vertex - loaded_vertices_);
}

int FlatPatch::global_halfedge(int halfedge) const {
  const int edge = halfedge / 2;
  const int global =
      edge < loaded_edges_ ? edge_handle_[edge] : mesh_edges_ + (edge - loaded_edges_);
  return 2 * global + halfedge % 2;
}

int FlatPatch::global_face(int face) const { return face_handle_[face]; }

std::array<int, 3> FlatPatch::corners(int face) const {
  const int h = face_halfedge_[face];
  return {to_[h], to_[next_[h]], to_[next_[next_[h]]]};
}

std::array<int, 3> FlatPatch::edges(int face) const {
  const int h = face_halfedge_[face];
  return {h / 2, next_[h] / 2, next_[next_[h]] / 2};
}

void FlatPatch::split(int face, const Point& position, double scale) {
  const int ab = face_halfedge_[face], bc = next_[ab], ca = next_[bc];
  const int a = to_[ca], b = to_[ab], c = to_[bc];
  const int v = static_cast<int>(points_.size());
  points_.push_back(position);
  scales_.push_back(scale);
  const int bv = 2 * add_edge(b, v), cv = 2 * add_edge(c, v), av = 2 * add_edge(a, v);
  vertex_halfedge_.push_back(global_halfedge(av + 1));
  count_edge(b, v, +1);
  count_edge(c, v, +1);
  count_edge(a, v, +1);
  // OpenMesh makes the face starting at b -> c first, but its vf_range(v) hands the one starting
  // at c -> a to the patch first: local faces follow the patch, handles the mesh.
  const int after_ca = face_count(), after_bc = after_ca + 1;
  const int handle = mesh_faces_ + (face_count() - loaded_faces_);
  link(ab, bv, av + 1, face);
  link(ca, av, cv + 1, after_ca);
  link(bc, cv, bv + 1, after_bc);
  face_halfedge_.insert(face_halfedge_.end(), {ca, bc});
  face_handle_.insert(face_handle_.end(), {handle + 1, handle});
  refined_[face] = 1;
  refined_.insert(refined_.end(), {1, 1});
}

void FlatPatch::count_edge(int a, int b, int change) {
  edges_between_.find_or_insert(pair_key(a, b), 0) += change;
}

bool FlatPatch::has_edge(int a, int b) const {
  if (edges_between_.find(pair_key(a, b), 0) > 0) return true;
  return a < loaded_vertices_ && b < loaded_vertices_ && has_outside_edge(a, b);
}

// An edge of the mesh outside the patch joins two of the patch's vertices: refinement never
// changes those, so the mesh as copied tells.
bool FlatPatch::has_outside_edge(int a, int b) const {
  const VertexHandle from(vertex_handle_[a]), to(vertex_handle_[b]);
  for (const auto h : mesh_.voh_range(from)) {
    if (mesh_.to_vertex_handle(h) != to) continue;
    if (edge_index_.find(static_cast<std::uint64_t>(mesh_.edge_handle(h).idx()), -1) < 0) {
      return true;
    }
  }
  return false;
}

bool FlatPatch::swappable(int edge) const {
  const int h0 = 2 * edge, h1 = h0 + 1;
  if (face_[h0] < 0 || face_[h1] < 0) return false;
  const int c = to_[next_[h0]], d = to_[next_[h1]];
  if (!should_swap_quad(points_[to_[h1]], points_[to_[h0]], points_[c], points_[d])) return false;
  return c != d && !has_edge(c, d);
}

void FlatPatch::flip(int edge) {
  const int a0 = 2 * edge, b0 = a0 + 1;
  const int a1 = next_[a0], a2 = next_[a1], b1 = next_[b0], b2 = next_[b1];
  const int va0 = to_[a0], va1 = to_[a1], vb0 = to_[b0], vb1 = to_[b1];
  const int fa = face_[a0], fb = face_[b0];
  count_edge(va0, vb0, -1);
  count_edge(va1, vb1, +1);
  to_[a0] = va1;
  to_[b0] = vb1;
  link(a0, a2, b1, fa);
  link(b0, b2, a1, fb);
  face_halfedge_[fa] = a0;
  face_halfedge_[fb] = b0;
  if (vertex_halfedge_[va0] == global_halfedge(b0)) vertex_halfedge_[va0] = global_halfedge(a1);
  if (vertex_halfedge_[vb0] == global_halfedge(a0)) vertex_halfedge_[vb0] = global_halfedge(b1);
}

std::size_t FlatPatch::relax(int max_sweeps) {
  std::size_t swaps = 0;
  for (int sweep = 0; sweep < max_sweeps; ++sweep) {
    std::size_t swapped_now = 0;
    for (int face = 0; face < face_count(); ++face) {
      for (const int edge : edges(face)) {  // copied first: a swap relinks the face
        if (swappable(edge)) {
          flip(edge);
          ++swapped_now;
        }
      }
    }
    swaps += swapped_now;
    if (swapped_now == 0) break;
  }
  return swaps;
}

void FlatPatch::write_back(Mesh& mesh, const PatchTags& tags, Patch& patch) const {
  for (int v = loaded_vertices_; v < static_cast<int>(points_.size()); ++v) {
    const VertexHandle vertex = mesh.add_vertex(points_[v]);
    mesh.property(tags.scale, vertex) = scales_[v];
    mesh.property(tags.vertex_stage, vertex) = static_cast<std::uint8_t>(Stage::Refined);
    patch.new_vertices.push_back(vertex);
  }
  for (int e = loaded_edges_; e < static_cast<int>(to_.size() / 2); ++e) {
    mesh.new_edge(VertexHandle(global_vertex(to_[2 * e + 1])),
                  VertexHandle(global_vertex(to_[2 * e])));
  }
  for (int f = loaded_faces_; f < face_count(); ++f) mesh.new_face();
  write_links(mesh);
  for (int f = 0; f < face_count(); ++f) {
    if (refined_[f])
      mesh.property(tags.face_stage, FaceHandle(global_face(f))) =
          static_cast<std::uint8_t>(Stage::Refined);
    if (f >= loaded_faces_) patch.faces.push_back(FaceHandle(global_face(f)));
  }
}

void FlatPatch::write_links(Mesh& mesh) const {
  for (int h = 0; h < static_cast<int>(to_.size()); ++h) {
    if (face_[h] < 0) continue;  // outside the patch: never changed
    const HalfedgeHandle halfedge(global_halfedge(h));
    mesh.set_next_halfedge_handle(halfedge, HalfedgeHandle(global_halfedge(next_[h])));
    mesh.set_vertex_handle(halfedge, VertexHandle(global_vertex(to_[h])));
    mesh.set_face_handle(halfedge, FaceHandle(global_face(face_[h])));
  }
  for (int f = 0; f < face_count(); ++f) {
    mesh.set_halfedge_handle(FaceHandle(global_face(f)),
                             HalfedgeHandle(global_halfedge(face_halfedge_[f])));
  }
  for (int v = 0; v < static_cast<int>(points_.size()); ++v) {
    mesh.set_halfedge_handle(VertexHandle(global_vertex(v)), HalfedgeHandle(vertex_halfedge_[v]));
  }
}

}  // namespace holefill::detail
