#include "holefill/borders.h"

#include <cmath>
#include <cstdio>

#include "safe_scale.h"

namespace holefill {
namespace {

// Rounding in files and exports moves a point off its plane by far less than this share of the
// loop's perimeter.
constexpr double kFlatRelativeTolerance = 1e-6;

// Half the sum of the cross products along the loop: its length is the area the loop encloses
// on the plane it is most spread over (exactly its area when the loop is planar), its direction
// that plane's normal.
Point vector_area(const Mesh& mesh, const Hole& hole) {
  Point sum(0.0, 0.0, 0.0);
  const std::size_t n = hole.vertices.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point a = mesh.point(hole.vertices[i]) - hole.centroid;
    const Point b = mesh.point(hole.vertices[(i + 1) % n]) - hole.centroid;
    sum += OpenMesh::cross(a, b);
  }
  return 0.5 * sum;
}

// Every vertex of the piece lies on the plane of its loop `hole` (up to rounding): a patch across
// the loop would lie on the piece.
bool piece_lies_in_loop_plane(const Mesh& mesh, std::span<const FaceHandle> piece_faces,
                              const Hole& hole, const Point& vector_area) {
  const double length = vector_area.norm();
  if (length == 0.0) return false;
  const Point normal = vector_area / length;
  const double tolerance = kFlatRelativeTolerance * hole.perimeter;
  for (const auto f : piece_faces) {
    for (const auto v : mesh.fv_range(f)) {
      if (std::abs(OpenMesh::dot(mesh.point(v) - hole.centroid, normal)) > tolerance) return false;
    }
  }
  return true;
}

// The piece lies over its loop's plane like a height field: its faces turned away from the
// loop's normal (the loop runs against the faces' orientation) cover at most this share of its
// area.
constexpr double kFoldedShareOfHeightField = 0.01;

bool piece_is_height_field_over(const Mesh& mesh, const MeshPieces& pieces, const MeshPiece& piece,
                                const Point& vector_area) {
  // The sum only grows: once over the limit it stays over (most pieces are no height field,
  // and summing all of a big one's faces took 6 % of filling a 1.4M-face mesh).
  const double limit = kFoldedShareOfHeightField * piece.area;
  double folded = 0.0;
  for (const auto f : pieces.faces_of(piece)) {
    const Point n = mesh.calc_face_normal(f);
    if (OpenMesh::dot(n, vector_area) >= 0.0) folded += mesh.calc_face_area(f);
    if (folded > limit) return false;
  }
  return folded <= limit;
}

std::string percent(double share) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f%%", 100.0 * share);
  return text;
}

}  // namespace

const char* to_string(LoopKind kind) {
  switch (kind) {
    case LoopKind::Hole:
      return "hole";
    case LoopKind::Border:
      return "border";
    case LoopKind::FlatPiece:
      return "flat piece";
  }
  return "?";
}

std::vector<LoopClass> classify_loops(const Mesh& mesh, const std::vector<Hole>& holes,
                                      const MeshPieces& pieces, double border_share) {
  // Shares and plane tests do not depend on the scale, but squared lengths overflow beyond
  // coordinates of about 1e77 and underflow below about 1e-77 (safe_scale.h): at 1e78 every
  // area was infinite and every widest loop "the rim of a flat piece", at 1e-100 every area 0
  // and a hole a "0 %" border. Such a mesh is classified on a copy scaled by a power of two.
  if (!detail::SafeScale::leaves_alone(detail::SafeScale::largest_coordinate(mesh))) {
    Mesh scaled = mesh;
    const detail::SafeScale scale(scaled);
    std::vector<Hole> scaled_holes;
    for (const auto& hole : holes) {
      scaled_holes.push_back(hole_through(scaled, hole.halfedges.front()));
      scaled_holes.back().id = hole.id;
    }
    return classify_loops(scaled, scaled_holes, mesh_pieces(scaled), border_share);
  }
  std::vector<LoopClass> classes(holes.size());
  std::vector<Point> areas(holes.size());
  std::vector<double> enclosed_sum(pieces.pieces.size(), 0.0);
  std::vector<int> widest(pieces.pieces.size(), -1);
  for (std::size_t i = 0; i < holes.size(); ++i) {
    LoopClass& c = classes[i];
    const FaceHandle inside = mesh.opposite_face_handle(holes[i].halfedges.front());
    c.piece = pieces.piece_of_face[inside.idx()];
    c.on_small_piece = pieces.pieces[c.piece].small;
    areas[i] = vector_area(mesh, holes[i]);
    c.enclosed_area = areas[i].norm();
    enclosed_sum[c.piece] += c.enclosed_area;
    int& w = widest[c.piece];
    if (w < 0 || c.enclosed_area > classes[w].enclosed_area) w = static_cast<int>(i);
  }
  for (std::size_t i = 0; i < holes.size(); ++i) {
    LoopClass& c = classes[i];
    const MeshPiece& piece = pieces.pieces[c.piece];
    const double closed_area = piece.area + enclosed_sum[c.piece] - c.enclosed_area;
    c.spanned_share = closed_area > 0.0 ? c.enclosed_area / closed_area : 0.0;
    const bool widest_loop = widest[c.piece] == static_cast<int>(i);
    if (widest_loop && piece_lies_in_loop_plane(mesh, pieces.faces_of(piece), holes[i], areas[i])) {
      c.kind = LoopKind::FlatPiece;
      c.reason = piece.lone_triangle()
                     ? "the rim of a lone triangle (face " +
                           std::to_string(pieces.faces[piece.first].idx() + 1) +
                           "): a patch would only cover it with a copy of itself"
                     : "the rim of a flat piece of " + std::to_string(piece.face_count) +
                           " faces: a patch would lie on the piece itself";
    } else if (widest_loop && c.spanned_share >= border_share) {
      c.kind = LoopKind::Border;
      c.reason = "the widest loop of its piece: a patch across it would span " +
                 percent(c.spanned_share) + " of the piece's area (borders from " +
                 percent(border_share) + ")";
    } else if (widest_loop && border_share <= 1.0 &&
               piece_is_height_field_over(mesh, pieces, piece, areas[i])) {
      c.kind = LoopKind::Border;
      c.reason =
          "the widest loop of its piece, which lies over it like a height field (a patch "
          "across it would span " +
          percent(c.spanned_share) + " of the piece's area)";
    }
  }
  return classes;
}

}  // namespace holefill
