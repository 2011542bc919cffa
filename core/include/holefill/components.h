// The pieces of a mesh: faces joined through shared edges. Scans and STL soups carry lone
// triangles and small floating pieces beside the surface; they are reported as what they are
// rather than as holes, and can be dropped before filling.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "holefill/mesh.h"

namespace holefill {

// A piece is small when it is not the largest and is a lone triangle or has at most this share of
// the mesh's faces.
inline constexpr double kSmallPieceShare = 0.01;

struct MeshPiece {
  std::size_t first = 0;  // its faces are MeshPieces::faces[first, first + face_count)
  std::size_t face_count = 0;
  double area = 0.0;
  bool largest = false;  // the piece with the most faces (the first of them on a tie)
  bool small = false;    // not the largest; one face, or at most kSmallPieceShare of the faces
  bool lone_triangle() const { return face_count == 1; }
};

// Four bytes a face for the face lists and four for the piece of each face: on a big mesh the
// pieces are found beside the whole mesh, at the peak of the memory that preparing it takes.
struct MeshPieces {
  std::vector<MeshPiece> pieces;        // ordered by their lowest face index
  std::vector<FaceHandle> faces;        // every live face, piece after piece, in face order
  std::vector<int> piece_of_face;       // index into pieces, per face (-1: a deleted face)
  std::size_t lone_triangles = 0;       // pieces of one face
  std::size_t small_pieces = 0;         // small pieces of more than one face
  std::size_t largest_small_piece = 0;  // faces of the largest small piece (or lone triangle)

  std::span<const FaceHandle> faces_of(const MeshPiece& piece) const {
    return {faces.data() + piece.first, piece.face_count};
  }
};

// The mesh's pieces (faces joined by edges; vertices shared without an edge do not join), each
// piece's faces listed and its area summed in face order.
MeshPieces mesh_pieces(const Mesh& mesh);

struct RemovedPieces {
  std::size_t pieces = 0;
  std::size_t faces = 0;
  std::size_t vertices = 0;  // vertices no face used any more, removed with their pieces
};

// Removes every piece of at most max_faces faces except the largest piece, and the vertices
// only they used. Other vertices and faces keep their positions and properties; indices change
// (OpenMesh's garbage collection moves the last elements into the freed places).
RemovedPieces remove_small_pieces(Mesh& mesh, std::size_t max_faces);

}  // namespace holefill
