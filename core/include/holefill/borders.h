// What each boundary loop is: a hole in a surface, the border of an open surface (a terrain,
// a face scan, a dome), or the rim of a flat piece (a lone triangle, a plate): a patch across
// that would lie on the piece itself, so it is never filled. A loop is a border when it is the loop
// of its piece that encloses the most area and a patch across it would span a large share of
// the piece: the area its polygon encloses (the length of its vector area, i.e. its area
// projected on its best-fitting plane), against the piece's own area with its other loops
// closed; or when the piece lies over that loop's plane like a height field (a rugged terrain
// whose area is many times its footprint). A hole in a closed surface spans a small share (a
// bunny's base, a cut-off cap) and has the surface on both sides of its plane; the border of a
// gentle height field spans nearly all of it, a hemisphere's rim half of it.
#pragma once

#include <string>
#include <vector>

#include "holefill/components.h"
#include "holefill/holes.h"
#include "holefill/mesh.h"

namespace holefill {

// The share from which a piece's widest loop counts as its border: between a hemisphere (1/2:
// a dome is open) and a cup as deep as it is wide (1/3: a cup misses its lid).
inline constexpr double kDefaultBorderShare = 0.4;

enum class LoopKind {
  Hole,
  Border,     // fill only when borders are not kept
  FlatPiece,  // the widest loop of a piece lying in one plane (a lone triangle is one): never
};

const char* to_string(LoopKind kind);

struct LoopClass {
  LoopKind kind = LoopKind::Hole;
  int piece = -1;               // index into mesh_pieces(mesh).pieces
  bool on_small_piece = false;  // the piece is small (components.h)
  double enclosed_area = 0.0;   // the length of the loop's vector area
  // enclosed_area / (the piece's area + the enclosed areas of its other loops)
  double spanned_share = 0.0;
  std::string reason;  // for a border or a flat piece: why, in words
};

// One class per hole of `holes` (find_holes(mesh)), in the same order. border_share: see
// kDefaultBorderShare; a value above 1 makes no loop a border.
std::vector<LoopClass> classify_loops(const Mesh& mesh, const std::vector<Hole>& holes,
                                      const MeshPieces& pieces,
                                      double border_share = kDefaultBorderShare);

}  // namespace holefill
