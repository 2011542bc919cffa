#include "flat_patch.h"

#include <algorithm>
#include <bit>
#include <stdexcept>

#include "delaunay_swap.h"

namespace holefill::detail {
namespace {

// The key of an unordered vertex pair (never FlatIndexMap's empty key: indices are below 2^31).
std::uint64_t pair_key(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b));
  const auto hi = static_cast<std::uint64_t>(std::max(a, b));
  return lo << 32 | hi;
}

}  // namespace

int FaceFlags::next(int face, int end) const {
  auto word = static_cast<std::size_t>(face) / 64;
  if (word >= words_.size()) return end;
  std::uint64_t bits = words_[word] & (~std::uint64_t{0} << (face & 63));
  while (bits == 0) {
    if (++word == words_.size()) return end;
    bits = words_[word];
  }
  return std::min(end, static_cast<int>(64 * word) + std::countr_zero(bits));
}

FlatPatch::FlatPatch(const Mesh& mesh, const Patch& patch, OpenMesh::VPropHandleT<double> scale)
    : mesh_(mesh),
      mesh_vertices_(static_cast<int>(mesh.n_vertices())),
      mesh_edges_(static_cast<int>(mesh.n_edges())),
      mesh_faces_(static_cast<int>(mesh.n_faces())),
      edge_index_(2 * patch.faces.size()),
      vertex_index_(patch.faces.size()),
      edges_between_(2 * patch.faces.size()) {
  for (const auto f : patch.faces) {
    const HalfedgeHandle first = mesh.halfedge_handle(f);
    const HalfedgeHandle second = mesh.next_halfedge_handle(first);
    const HalfedgeHandle third = mesh.next_halfedge_handle(second);
    const int h0 = local_halfedge(mesh, first, scale), h1 = local_halfedge(mesh, second, scale),
              h2 = local_halfedge(mesh, third, scale);
    if (face_[h0] >= 0 || face_[h1] >= 0 || face_[h2] >= 0) {
      throw std::logic_error("refinement: the patch lists a face twice");
    }
    link(h0, h1, h2, add_face(h0, f.idx()));
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
  const int edge_index = halfedge.idx() >> 1, side = halfedge.idx() & 1;
  const int known = edge_index_.find(static_cast<std::uint64_t>(edge_index), -1);
  if (known >= 0) return 2 * known + side;
  const HalfedgeHandle first = mesh.halfedge_handle(mesh.edge_handle(halfedge), 0);
  const int from = add_vertex(mesh, mesh.from_vertex_handle(first), scale);
  const int to = add_vertex(mesh, mesh.to_vertex_handle(first), scale);
  const int edge = add_edge(from, to, edge_index);
  edge_index_.find_or_insert(static_cast<std::uint64_t>(edge_index), edge);
  return 2 * edge + side;
}

int FlatPatch::add_edge(int from, int to, int handle) {
  const int edge = static_cast<int>(edge_handle_.size());
  to_.insert(to_.end(), {to, from});
  next_.insert(next_.end(), {-1, -1});
  face_.insert(face_.end(), {-1, -1});
  edge_handle_.push_back(handle);
  edge_settled_.push_back(0);
  return edge;
}

// A face to be tested for a split, with edges to be tested for swaps.
int FlatPatch::add_face(int halfedge, int handle) {
  const int face = face_count();
  face_halfedge_.push_back(halfedge);
  face_handle_.push_back(handle);
  refined_.push_back(0);
  untested_.grow(face + 1);
  unsettled_.grow(face + 1);
  untested_.set(face);
  unsettled_.set(face);
  return face;
}

// One of the edge's faces changed: its swap test may answer otherwise now, on either face's visit.
void FlatPatch::unsettle_edge(int edge) {
  edge_settled_[edge] = 0;
  for (const int face : {face_[2 * edge], face_[2 * edge + 1]}) {
    if (face >= 0) unsettled_.set(face);
  }
}

void FlatPatch::link(int h0, int h1, int h2, int face) {
  next_[h0] = h1;
  next_[h1] = h2;
  next_[h2] = h0;
  face_[h0] = face_[h1] = face_[h2] = face;
}

std::array<int, 3> FlatPatch::corners(int face) const {
  const int h = face_halfedge_[face];
  return {to_[h], to_[next_[h]], to_[next_[next_[h]]]};
}

std::array<int, 3> FlatPatch::edges(int face) const {
  const int h = face_halfedge_[face];
  return {h >> 1, next_[h] >> 1, next_[next_[h]] >> 1};
}

void FlatPatch::split(int face, const Point& position, double scale) {
  const int ab = face_halfedge_[face], bc = next_[ab], ca = next_[bc];
  const int a = to_[ca], b = to_[ab], c = to_[bc];
  const int v = static_cast<int>(points_.size());
  points_.push_back(position);
  scales_.push_back(scale);
  vertex_handle_.push_back(mesh_vertices_ + (v - loaded_vertices_));
  const int first_edge = mesh_edges_ + (static_cast<int>(edge_handle_.size()) - loaded_edges_);
  const int bv = 2 * add_edge(b, v, first_edge), cv = 2 * add_edge(c, v, first_edge + 1),
            av = 2 * add_edge(a, v, first_edge + 2);
  vertex_halfedge_.push_back(global_halfedge(av + 1));
  // OpenMesh makes the face starting at b -> c first, but its vf_range(v) hands the one starting
  // at c -> a to the patch first: local faces follow the patch, handles the mesh.
  const int first_face = mesh_faces_ + (face_count() - loaded_faces_);
  const int after_ca = add_face(ca, first_face + 1), after_bc = add_face(bc, first_face);
  link(ab, bv, av + 1, face);
  link(ca, av, cv + 1, after_ca);
  link(bc, cv, bv + 1, after_bc);
  refined_[face] = refined_[after_ca] = refined_[after_bc] = 1;
  untested_.set(face);
  for (const int h : {ab, bc, ca, bv, cv, av}) unsettle_edge(h >> 1);
}

void FlatPatch::count_edge(int a, int b, int change) {
  if (a < loaded_vertices_ && b < loaded_vertices_) {
    edges_between_.find_or_insert(pair_key(a, b), 0) += change;
  }
}

// Whether an edge joins the two vertices; from_a and from_b are halfedges out of each. A vertex
// that refinement added is surrounded by patch faces, so its own ring answers; between two of the
// patch's first vertices the counts and the mesh outside the patch do.
bool FlatPatch::has_edge(int a, int from_a, int b, int from_b) const {
  if (a < loaded_vertices_ && b < loaded_vertices_) {
    return edges_between_.find(pair_key(a, b), 0) > 0 || has_outside_edge(a, b);
  }
  const int other = a < loaded_vertices_ ? a : b;
  const int start = a < loaded_vertices_ ? from_b : from_a;
  int h = start;
  do {
    if (to_[h] == other) return true;
    h = next_[h ^ 1];  // the next halfedge out of the same vertex, clockwise
  } while (h != start);
  return false;
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

bool FlatPatch::swappable(int edge) {
  const int h0 = 2 * edge, h1 = h0 + 1;
  if (edge_settled_[edge]) return false;
  if (face_[h0] < 0 || face_[h1] < 0) {  // on the patch's border, for good
    edge_settled_[edge] = 1;
    return false;
  }
  const int c = to_[next_[h0]], d = to_[next_[h1]];
  if (!should_swap_quad(points_[to_[h1]], points_[to_[h0]], points_[c], points_[d])) {
    edge_settled_[edge] = 1;
    return false;
  }
  return c != d && !has_edge(c, next_[next_[h0]], d, next_[next_[h1]]);
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
  untested_.set(fa);
  untested_.set(fb);
  for (const int h : {a1, a2, b1, b2}) unsettle_edge(h >> 1);
  // The new edge's opposite angles are the old edge's swapped ones and the other way round (the
  // same atan2 of the same vectors), so the swap that made it says it would not swap back.
  edge_settled_[edge] = 1;
}

std::size_t FlatPatch::relax(int max_sweeps) {
  std::size_t swaps = 0;
  for (int sweep = 0; sweep < max_sweeps; ++sweep) {
    std::size_t swapped_now = 0;
    // A sweep over every face, where a face whose edges are all settled would swap nothing.
    for (int face = unsettled_.next(0, face_count()); face < face_count();
         face = unsettled_.next(face + 1, face_count())) {
      unsettled_.clear(face);
      for (const int edge : edges(face)) {  // copied first: a swap relinks the face
        if (swappable(edge)) {
          flip(edge);
          ++swapped_now;
        } else if (!edge_settled_[edge]) {
          unsettled_.set(face);  // a swap refused: ask again next sweep
        }
      }
    }
    swaps += swapped_now;
    if (swapped_now == 0) break;
  }
  return swaps;
}

void FlatPatch::write_back(Mesh& mesh, const PatchTags& tags, Patch& patch) const {
  if (static_cast<int>(mesh.n_vertices()) != mesh_vertices_ ||
      static_cast<int>(mesh.n_edges()) != mesh_edges_ ||
      static_cast<int>(mesh.n_faces()) != mesh_faces_) {
    throw std::logic_error("refinement: the mesh changed while the patch was refined apart");
  }
  // One resize gives the new elements what OpenMesh's add_vertex, new_edge and new_face would
  // (default items and property values) without resizing every property once per element.
  const int vertices = static_cast<int>(points_.size());
  mesh.resize(mesh_vertices_ + vertices - loaded_vertices_,
              mesh_edges_ + static_cast<int>(edge_handle_.size()) - loaded_edges_,
              mesh_faces_ + face_count() - loaded_faces_);
  for (int v = loaded_vertices_; v < vertices; ++v) {
    const VertexHandle vertex(vertex_handle_[v]);
    mesh.set_point(vertex, points_[v]);
    mesh.property(tags.scale, vertex) = scales_[v];
    mesh.property(tags.vertex_stage, vertex) = static_cast<std::uint8_t>(Stage::Refined);
    patch.new_vertices.push_back(vertex);
  }
  write_links(mesh);
  for (int f = 0; f < face_count(); ++f) {
    const FaceHandle face(face_handle_[f]);
    if (refined_[f])
      mesh.property(tags.face_stage, face) = static_cast<std::uint8_t>(Stage::Refined);
    if (f >= loaded_faces_) patch.faces.push_back(face);
  }
}

void FlatPatch::write_links(Mesh& mesh) const {
  for (int f = 0; f < face_count(); ++f) {
    const FaceHandle face(face_handle_[f]);
    mesh.set_halfedge_handle(face, HalfedgeHandle(global_halfedge(face_halfedge_[f])));
    const int first = face_halfedge_[f];
    int h = first;
    do {
      const HalfedgeHandle halfedge(global_halfedge(h));
      mesh.set_next_halfedge_handle(halfedge, HalfedgeHandle(global_halfedge(next_[h])));
      mesh.set_vertex_handle(halfedge, VertexHandle(vertex_handle_[to_[h]]));
      mesh.set_face_handle(halfedge, face);
      h = next_[h];
    } while (h != first);
  }
  for (int v = 0; v < static_cast<int>(points_.size()); ++v) {
    mesh.set_halfedge_handle(VertexHandle(vertex_handle_[v]), HalfedgeHandle(vertex_halfedge_[v]));
  }
}

}  // namespace holefill::detail
