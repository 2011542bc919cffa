#include "holefill/components.h"

#include <algorithm>

namespace holefill {

MeshPieces mesh_pieces(const Mesh& mesh) {
  MeshPieces result;
  result.piece_of_face.assign(mesh.n_faces(), -1);
  std::vector<FaceHandle> stack;
  for (const auto start : mesh.faces()) {
    if (result.piece_of_face[start.idx()] >= 0) continue;
    const int id = static_cast<int>(result.pieces.size());
    MeshPiece piece;
    result.piece_of_face[start.idx()] = id;
    stack.push_back(start);
    while (!stack.empty()) {
      const FaceHandle f = stack.back();
      stack.pop_back();
      piece.faces.push_back(f);
      piece.area += mesh.calc_face_area(f);
      for (const auto neighbour : mesh.ff_range(f)) {
        if (result.piece_of_face[neighbour.idx()] < 0) {
          result.piece_of_face[neighbour.idx()] = id;
          stack.push_back(neighbour);
        }
      }
    }
    result.pieces.push_back(std::move(piece));
  }
  if (result.pieces.empty()) return result;
  const auto largest = std::max_element(
      result.pieces.begin(), result.pieces.end(),
      [](const MeshPiece& a, const MeshPiece& b) { return a.faces.size() < b.faces.size(); });
  largest->largest = true;
  const double small_limit = kSmallPieceShare * static_cast<double>(mesh.n_faces());
  for (auto& piece : result.pieces) {
    piece.small = !piece.largest &&
                  (piece.lone_triangle() || static_cast<double>(piece.faces.size()) <= small_limit);
    if (!piece.small) continue;
    ++(piece.lone_triangle() ? result.lone_triangles : result.small_pieces);
    result.largest_small_piece = std::max(result.largest_small_piece, piece.faces.size());
  }
  return result;
}

RemovedPieces remove_small_pieces(Mesh& mesh, std::size_t max_faces) {
  RemovedPieces removed;
  const MeshPieces found = mesh_pieces(mesh);
  std::vector<VertexHandle> corners;
  for (const auto& piece : found.pieces) {
    if (piece.largest || piece.faces.size() > max_faces) continue;
    ++removed.pieces;
    removed.faces += piece.faces.size();
    for (const auto f : piece.faces) {
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
