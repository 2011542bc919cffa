#include "holefill/components.h"

#include <algorithm>

#include "deletion_flags.h"
#include "sets_by_lowest.h"

namespace holefill {

MeshPieces mesh_pieces(const Mesh& mesh) {
  MeshPieces result;
  result.piece_of_face.assign(mesh.n_faces(), -1);
  for (const auto f : mesh.faces()) result.piece_of_face[f.idx()] = f.idx();
  const int count = detail::number_sets_by_lowest(result.piece_of_face, [&mesh](auto join) {
    for (const auto e : mesh.edges()) {
      const FaceHandle a = mesh.face_handle(mesh.halfedge_handle(e, 0));
      const FaceHandle b = mesh.face_handle(mesh.halfedge_handle(e, 1));
      if (a.is_valid() && b.is_valid()) join(a.idx(), b.idx());
    }
  });
  result.pieces.resize(static_cast<std::size_t>(count));
  for (const auto f : mesh.faces()) {
    MeshPiece& piece = result.pieces[static_cast<std::size_t>(result.piece_of_face[f.idx()])];
    ++piece.face_count;
    piece.area += mesh.calc_face_area(f);
  }
  std::size_t first = 0;
  for (auto& piece : result.pieces) {
    piece.first = first;
    first += piece.face_count;
  }
  result.faces.resize(first);
  std::vector<std::size_t> next(result.pieces.size());
  for (std::size_t p = 0; p < next.size(); ++p) next[p] = result.pieces[p].first;
  for (const auto f : mesh.faces()) {
    result.faces[next[static_cast<std::size_t>(result.piece_of_face[f.idx()])]++] = f;
  }
  if (result.pieces.empty()) return result;
  const auto largest = std::max_element(
      result.pieces.begin(), result.pieces.end(),
      [](const MeshPiece& a, const MeshPiece& b) { return a.face_count < b.face_count; });
  largest->largest = true;
  const double small_limit = kSmallPieceShare * static_cast<double>(mesh.n_faces());
  for (auto& piece : result.pieces) {
    piece.small = !piece.largest &&
                  (piece.lone_triangle() || static_cast<double>(piece.face_count) <= small_limit);
    if (!piece.small) continue;
    ++(piece.lone_triangle() ? result.lone_triangles : result.small_pieces);
    result.largest_small_piece = std::max(result.largest_small_piece, piece.face_count);
  }
  return result;
}

RemovedPieces remove_small_pieces(Mesh& mesh, std::size_t max_faces) {
  RemovedPieces removed;
  const MeshPieces found = mesh_pieces(mesh);
  const detail::DeletionFlags flags(mesh);
  std::vector<VertexHandle> corners;
  for (const auto& piece : found.pieces) {
    if (piece.largest || piece.face_count > max_faces) continue;
    ++removed.pieces;
    removed.faces += piece.face_count;
    for (const auto f : found.faces_of(piece)) {
      for (const auto v : mesh.fv_range(f)) corners.push_back(v);
      mesh.delete_face(f, false);
    }
  }
  if (removed.pieces == 0) return removed;
  // Only vertices that the removed faces used and no face uses now go; isolated vertices the
  // file had stay, as they did before.
  for (const auto v : corners) {
    if (!mesh.status(v).deleted() && mesh.is_isolated(v)) {
      mesh.delete_vertex(v, false);
      ++removed.vertices;
    }
  }
  mesh.garbage_collection();
  return removed;
}

}  // namespace holefill
